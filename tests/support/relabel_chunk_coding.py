# SPDX-License-Identifier: Apache-2.0
# Used by the CLI tests (not a test itself). Sets the index entry's `coding` of the first
# data brick of a store to CODING (0 codec chain, 1 fpzip, 2 zfp) and recomputes every
# checksum a reader checks (index section, section table, footer, manifest): a store whose
# chunk claims a coding its variable's codec does not allow. Prints the relabelled node
# as "STEP_FILE VARIABLE NODE".
# Usage: relabel_chunk_coding.py STORE CODING
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from store_rewrite import data_bricks, fix_manifest, read_manifest, rewrite  # noqa: E402


def main():
    store, coding = Path(sys.argv[1]), int(sys.argv[2])
    raw, n, manifest = read_manifest(store)
    for entry, path, data, table, sections, v, node, at, *_ in data_bricks(store, manifest):
        section = sections[v]
        section[at + 13] = coding
        rewrite(path, data, table, v, bytes(section))
        fix_manifest(store, raw, n, entry)
        print(entry["file"], manifest["variables"][v]["name"], node)
        return
    raise SystemExit("no data brick in the store")


main()
