# SPDX-License-Identifier: Apache-2.0
# Used by the CLI tests (not a test itself). Replaces the stream of one fpzip chunk of a
# store with a crafted one and recomputes every checksum a reader checks (formats/store.md:
# stream, chunk, index section, section table, footer, manifest), as an attacker would.
# The index section holding the chunk is rewritten uncompressed; the other sections keep
# their bytes. Prints the forged node as "STEP_FILE VARIABLE NODE NX NY NZ".
# Usage: forge_fpzip_chunk.py STORE CRAFTED_CHUNK_FILE  (the crafted file is a chunk whose
# bytes from offset 16 are the stream; it is zero-padded or cut to the original's length)
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from store_rewrite import data_bricks, fix_manifest, read_manifest, rewrite, xxh3  # noqa: E402


def stream_seed(nx, ny, nz, t):
    return nx | ny << 20 | nz << 40 | t << 60


def brick_of(chunk, brick):
    """The (nx, ny, nz, t) whose seed reproduces the chunk's stream checksum."""
    want = struct.unpack_from("<Q", chunk, 8)[0]
    stream = chunk[16:]
    for t in (0, 1):
        for nz in range(1, brick + 2):
            for ny in range(1, brick + 2):
                for nx in range(1, brick + 2):
                    if xxh3(stream, stream_seed(nx, ny, nz, t)) == want:
                        return nx, ny, nz, t
    raise SystemExit("no brick shape matches the chunk's stream checksum")


def main():
    store, crafted = Path(sys.argv[1]), Path(sys.argv[2]).read_bytes()[16:]
    raw, n, manifest = read_manifest(store)
    brick = manifest["octree"]["brick"]
    for entry, path, data, table, sections, v, node, at, c_off, c_size, coding in data_bricks(store, manifest):
        if coding != 1:
            continue
        chunk = bytes(data[c_off:c_off + c_size])
        nx, ny, nz, t = brick_of(chunk, brick)
        if (nx, ny, nz, t) != (5, 5, 5, 0) and len(sys.argv) < 4:
            continue  # the crafted streams fit float32 bricks of 5x5x5
        stream = (crafted + bytes(c_size))[:c_size - 16]
        forged = chunk[:8] + struct.pack("<Q", xxh3(stream, stream_seed(nx, ny, nz, t))) + stream
        data[c_off:c_off + c_size] = forged
        section = sections[v]
        struct.pack_into("<Q", section, at + 16, xxh3(forged))
        rewrite(path, data, table, v, bytes(section))
        fix_manifest(store, raw, n, entry)
        print(entry["file"], manifest["variables"][v]["name"], node, nx, ny, nz)
        return
    raise SystemExit("no fpzip chunk of a 5x5x5 float32 brick in the store")


main()
