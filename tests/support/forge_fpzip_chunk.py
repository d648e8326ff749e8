# SPDX-License-Identifier: Apache-2.0
# Used by the CLI tests (not a test itself). Replaces the stream of one fpzip chunk of a
# store with a crafted one and recomputes every checksum a reader checks (formats/store.md:
# stream, chunk, index section, section table, footer, manifest), as an attacker would.
# The index section holding the chunk is rewritten uncompressed; the other sections keep
# their bytes. Prints the forged node as "STEP_FILE VARIABLE NODE NX NY NZ".
# Usage: forge_fpzip_chunk.py STORE CRAFTED_CHUNK_FILE  (the crafted file is a chunk whose
# bytes from offset 16 are the stream; it is zero-padded or cut to the original's length)
import ctypes
import json
import struct
import sys
from pathlib import Path

xxh = ctypes.CDLL("libxxhash.so.0")
xxh.XXH3_64bits.restype = ctypes.c_uint64
xxh.XXH3_64bits.argtypes = [ctypes.c_char_p, ctypes.c_size_t]
xxh.XXH3_64bits_withSeed.restype = ctypes.c_uint64
xxh.XXH3_64bits_withSeed.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_uint64]
zstd = ctypes.CDLL("libzstd.so.1")
zstd.ZSTD_decompress.restype = ctypes.c_size_t
zstd.ZSTD_decompress.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_char_p, ctypes.c_size_t]


def xxh3(b, seed=None):
    return xxh.XXH3_64bits(b, len(b)) if seed is None else xxh.XXH3_64bits_withSeed(b, len(b), seed)


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
    raw = (store / "MANIFEST").read_bytes()
    n = struct.unpack_from("<Q", raw, 16)[0]
    manifest = json.loads(raw[24:24 + n])
    brick = manifest["octree"]["brick"]
    node_count = manifest["octree"]["node_count"]
    for entry in manifest["steps"]:
        path = store / entry["file"]
        data = bytearray(path.read_bytes())
        table_offset, variables = struct.unpack_from("<QI", data, len(data) - 64)
        table = [list(struct.unpack_from("<IIQQQQQ", data, table_offset + 48 * v)) for v in range(variables)]
        for v, (_, codec, offset, stored, raw_size, _, _) in enumerate(table):
            section = bytes(data[offset:offset + stored])
            if codec == 1:
                out = ctypes.create_string_buffer(raw_size)
                got = zstd.ZSTD_decompress(out, raw_size, section, stored)
                assert got == raw_size, "zstd section did not decompress"
                section = out.raw
            section = bytearray(section)
            for node in range(node_count):
                at = 56 * node
                c_off, c_size, kind, coding = struct.unpack_from("<QIBB", section, at)
                if kind != 2 or coding != 1:
                    continue
                chunk = bytes(data[c_off:c_off + c_size])
                nx, ny, nz, t = brick_of(chunk, brick)
                if (nx, ny, nz, t) != (5, 5, 5, 0) and len(sys.argv) < 4:
                    continue  # the crafted streams fit float32 bricks of 5x5x5
                stream = (crafted + bytes(c_size))[:c_size - 16]
                forged = chunk[:8] + struct.pack("<Q", xxh3(stream, stream_seed(nx, ny, nz, t))) + stream
                data[c_off:c_off + c_size] = forged
                struct.pack_into("<Q", section, at + 16, xxh3(forged))
                rewrite(path, data, table, v, bytes(section))
                fix_manifest(store, raw, n, entry)
                print(entry["file"], manifest["variables"][v]["name"], node, nx, ny, nz)
                return
    raise SystemExit("no fpzip chunk of a 5x5x5 float32 brick in the store")


def rewrite(path, data, table, v, section):
    """Lays out the sections again (section v uncompressed), then the table and footer."""
    start = min(e[2] for e in table)
    sections = [bytes(data[e[2]:e[2] + e[3]]) for e in table]
    sections[v] = section
    table[v][1] = 0
    out = bytearray(data[:start])
    for i, s in enumerate(sections):
        table[i][2], table[i][3], table[i][5] = len(out), len(s), xxh3(s)
        out += s
    table_offset = len(out)
    table_bytes = b"".join(struct.pack("<IIQQQQQ", *e) for e in table)
    out += table_bytes
    footer = bytearray(data[len(data) - 64:])
    struct.pack_into("<Q", footer, 0, table_offset)
    struct.pack_into("<Q", footer, 32, xxh3(table_bytes))
    struct.pack_into("<Q", footer, 48, xxh3(bytes(footer[:48])))
    out += footer
    path.write_bytes(out)


def fix_manifest(store, raw, n, entry):
    """The step's size and footer checksum in the manifest, and the manifest's checksum."""
    path = store / entry["file"]
    data = path.read_bytes()
    footer_sum = struct.unpack_from("<Q", data, len(data) - 16)[0]
    payload = raw[24:24 + n].decode()
    old = '"footer_checksum": "%s",\n   "size": %d,' % (entry["footer_checksum"], entry["size"])
    new = '"footer_checksum": "%016x",\n   "size": %d,' % (footer_sum, len(data))
    assert old in payload, "manifest layout not as expected"
    payload = payload.replace(old, new).encode()
    head = bytearray(raw[:24])
    struct.pack_into("<Q", head, 16, len(payload))
    body = bytes(head) + payload
    (store / "MANIFEST").write_bytes(body + struct.pack("<Q", xxh3(body)))


main()
