#!/usr/bin/env python3
"""Reads WebDataset tar shards with Python's tarfile, as a training pipeline would.

Usage: read_shards.py OUT_DIR SHARD.tar...

Checks each member is a regular file whose name WebDataset splits into key and extension (its
regex in webdataset.tariterators.base_plus_ext), that the files of a sample are consecutive
(a key never comes back after another key) and extracts each member to OUT_DIR/NAME. Prints one
line per member, "SHARD<TAB>NAME<TAB>SIZE". Exit 1 with a message at the first problem.
"""
import os
import re
import sys
import tarfile

# webdataset 0.2 tariterators.base_plus_ext
BASE_PLUS_EXT = re.compile(r"^((?:.*/|)[^.]+)[.]([^/]*)$")


def main():
    out_dir, shards = sys.argv[1], sys.argv[2:]
    finished = set()  # keys whose samples ended
    current = None
    for shard in shards:
        if current is not None:  # a sample never spans two shards
            finished.add(current)
            current = None
        with tarfile.open(shard) as tar:
            for member in tar:
                if not member.isfile():
                    sys.exit(f"{shard}: {member.name}: not a regular file")
                m = BASE_PLUS_EXT.match(member.name)
                if not m:
                    sys.exit(f"{shard}: {member.name}: no key.extension split")
                key = m.group(1)
                if key != current:
                    if key in finished:
                        sys.exit(f"{shard}: {member.name}: sample {key} is not consecutive")
                    if current is not None:
                        finished.add(current)
                    current = key
                path = os.path.join(out_dir, member.name)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "wb") as f:
                    f.write(tar.extractfile(member).read())
                print(f"{shard}\t{member.name}\t{member.size}")


if __name__ == "__main__":
    main()
