#!/usr/bin/env python3
"""Byte comparison of the EXR files of two folders (tests/tools/render_matrix.sh). Every byte of
header and pixels must match, except the value of the `capDate` header attribute, which
OpenImageIO stamps with the time of writing. Exits 1 when any file differs or is missing."""
import os
import sys


def masked(path):
    data = bytearray(open(path, "rb").read())
    # OpenEXR attribute: name\0 type\0 int32 size, then the value.
    key = b"capDate\0string\0"
    at = data.find(key)
    if at >= 0:
        start = at + len(key)
        size = int.from_bytes(data[start:start + 4], "little")
        data[start + 4:start + 4 + size] = b"\0" * size
    return bytes(data)


def main(a, b):
    left = {f for f in os.listdir(a) if f.endswith(".exr")}
    right = {f for f in os.listdir(b) if f.endswith(".exr")}
    differ = [f for f in sorted(left & right)
              if masked(os.path.join(a, f)) != masked(os.path.join(b, f))]
    for f in differ:
        print("DIFFERS", f)
    for f in sorted(left ^ right):
        print("ONLY IN", a if f in left else b, f)
    print(f"{len(left & right) - len(differ)} identical, {len(differ)} differ, "
          f"{len(left ^ right)} on one side only")
    return 1 if differ or left ^ right else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
