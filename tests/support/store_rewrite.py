# SPDX-License-Identifier: Apache-2.0
# Used by the CLI tests (not a test itself): rewriting a store's step file as an attacker
# would, every checksum a reader checks recomputed (formats/store.md: index section,
# section table, footer, manifest).
import ctypes
import json
import struct

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



def read_manifest(store):
    """The MANIFEST's raw bytes, its payload size and the parsed payload."""
    raw = (store / "MANIFEST").read_bytes()
    n = struct.unpack_from("<Q", raw, 16)[0]
    return raw, n, json.loads(raw[24:24 + n])


def sections_of(data):
    """The step file's section table entries (lists) and each section's entry bytes,
    decompressed."""
    table_offset, variables = struct.unpack_from("<QI", data, len(data) - 64)
    table = [list(struct.unpack_from("<IIQQQQQ", data, table_offset + 48 * v)) for v in range(variables)]
    sections = []
    for (_, codec, offset, stored, raw_size, _, _) in table:
        section = bytes(data[offset:offset + stored])
        if codec == 1:
            out = ctypes.create_string_buffer(raw_size)
            got = zstd.ZSTD_decompress(out, raw_size, section, stored)
            assert got == raw_size, "zstd section did not decompress"
            section = out.raw
        sections.append(bytearray(section))
    return table, sections


def data_bricks(store, manifest):
    """Every data brick's index entry in every step file: (step entry of the manifest, step
    file path, its bytes, section table, sections, variable, node, entry offset in the
    section, chunk offset, chunk size, coding)."""
    for entry in manifest["steps"]:
        path = store / entry["file"]
        data = bytearray(path.read_bytes())
        table, sections = sections_of(data)
        for v, section in enumerate(sections):
            for node in range(manifest["octree"]["node_count"]):
                at = 56 * node
                c_off, c_size, kind, coding = struct.unpack_from("<QIBB", section, at)
                if kind == 2:
                    yield entry, path, data, table, sections, v, node, at, c_off, c_size, coding


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


