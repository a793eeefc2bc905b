#!/usr/bin/env python3
"""Edit one array of a DS file and write it back with valid CRCs: the damage a hand edit or
another program makes, which the checksum cannot catch (the stages must re-check the meaning).

    ds_edit.py FILE ARRAY VALUE[,VALUE...]    replace the values (same type; nan/inf allowed)
    ds_edit.py FILE ARRAY --index K VALUE     replace value K (0-based) only

The layout is the one of modules/core/include/core/ds.hpp."""
import struct
import sys
import zlib

NAME = 24
TYPES = {1: "q", 2: "d", 3: "s"}


def records(data):
    """Yield (start, end) of every array record (name .. CRC) after the header."""
    count = struct.unpack_from("<I", data, 12)[0]
    pos = 16 + 128 + 4
    for _ in range(count):
        start = pos
        rank = struct.unpack_from("<I", data, pos + NAME + 4)[0]
        pos += NAME + 8 + 8 * rank
        size = struct.unpack_from("<Q", data, pos)[0]
        pos += 8 + size + 4
        yield start, pos


def main():
    args = sys.argv[1:]
    index = None
    if "--index" in args:
        at = args.index("--index")
        index = int(args[at + 1])
        del args[at:at + 2]
    path, name, text = args
    data = bytearray(open(path, "rb").read())
    for start, end in records(data):
        if data[start:start + NAME].rstrip(b"\0").decode() != name:
            continue
        kind, rank = struct.unpack_from("<II", data, start + NAME)
        shape_end = start + NAME + 8 + 8 * rank
        size = struct.unpack_from("<Q", data, shape_end)[0]
        payload = shape_end + 8
        code = TYPES[kind]
        if code == "s":
            sys.exit("ds_edit: text arrays are not edited")
        count = size // 8
        values = list(struct.unpack_from("<%d%s" % (count, code), data, payload))
        parse = float if code == "d" else int
        if index is None:
            new = [parse(v) for v in text.split(",")]
            if len(new) != count:
                sys.exit("ds_edit: %s holds %d values, %d given" % (name, count, len(new)))
            values = new
        else:
            values[index] = parse(text)
        struct.pack_into("<%d%s" % (count, code), data, payload, *values)
        crc = zlib.crc32(bytes(data[start:end - 4])) & 0xFFFFFFFF
        struct.pack_into("<I", data, end - 4, crc)
        open(path, "wb").write(data)
        return
    sys.exit("ds_edit: no array %s in %s" % (name, path))


if __name__ == "__main__":
    main()
