#!/usr/bin/env python3
"""check_levels_of_detail.py PROGRAM INPUT WORK RATIO SURFACE: runs PROGRAM on INPUT
(binary little-endian PLY, or LAS) three times, into WORK:
  direct: --ratio RATIO
  lod:    --lod --ratio RATIO --importance --indices lod.txt
  kept:   --ratio RATIO --indices kept.txt
and checks the outputs with readers of its own, written from the PLY and LAS
specifications and sharing no code with the program:
- lod holds every input point once, in the order of lod.txt, each the input
  point of the row lod.txt names (for LAS, its record, byte for byte, then the
  8 bytes of the attribute);
- its first m points are the direct run's m points;
- PLY: scalar_rank counts 0 to n - 1 in file order;
- the importance is finite, within [0, 1] (the default mode's feature
  strength), 0 everywhere when SURFACE is "flat" and not when it is
  "features"; in LAS, the Extra Bytes VLR declares it as
  the double 'importance' after descriptors covering the records' own extra
  bytes, the header's record length, offset to points and VLR count account
  for it, and the EVLRs follow the points, as the input's;
- kept.txt is the first m lines of lod.txt, and kept equals direct byte for
  byte (--indices changes nothing else).
Prints what it checked; exits 1 on the first difference."""

import math
import os
import struct
import subprocess
import sys

PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def read_ply(path):
    """The vertex properties' names and the vertices as tuples, from a
    binary little-endian PLY whose only element is the vertices."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    names, formats, count = [], "<", 0
    for line in data[:end].decode("ascii").splitlines():
        words = line.split()
        if words[:1] == ["format"] and words[1] != "binary_little_endian":
            fail(path + ": expected binary_little_endian, got " + words[1])
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            formats += PLY_TYPES[words[1]]
            names.append(words[2])
    size = struct.calcsize(formats)
    rows = [struct.unpack_from(formats, data, end + i * size) for i in range(count)]
    return names, rows


def las_layout(data):
    header_size = struct.unpack_from("<H", data, 94)[0]
    offset, vlrs = struct.unpack_from("<II", data, 96)
    point_format, length = data[104], struct.unpack_from("<H", data, 105)[0]
    count = struct.unpack_from("<I", data, 107)[0]
    if data[25] >= 4 and struct.unpack_from("<Q", data, 247)[0]:
        count = struct.unpack_from("<Q", data, 247)[0]
    return {"header_size": header_size, "offset": offset, "vlrs": vlrs, "format": point_format,
            "length": length, "count": count}


def las_records(data):
    h = las_layout(data)
    return [data[h["offset"] + i * h["length"]:h["offset"] + (i + 1) * h["length"]] for i in range(h["count"])]


def extra_bytes_descriptors(data):
    h = las_layout(data)
    at = h["header_size"]
    for _ in range(h["vlrs"]):
        user = data[at + 2:at + 18].split(b"\0")[0]
        record_id, length = struct.unpack_from("<HH", data, at + 18)
        if user == b"LASF_Spec" and record_id == 4:
            return [data[at + 54 + d:at + 54 + d + 192] for d in range(0, length, 192)]
        at += 54 + length
    return []


def declared_size(descriptor):
    sizes = [0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8]
    kind = descriptor[2]
    if kind == 0:
        return descriptor[3]
    if kind <= 10:
        return sizes[kind]
    return sizes[(kind - 11) % 10 + 1] * ((kind - 11) // 10 + 2)


BASE_SIZES = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67]


def check_importance(values, surface):
    if not all(math.isfinite(v) and 0. <= v <= 1. for v in values):
        fail("an importance is not within [0, 1]")
    if any(v > 0. for v in values) != (surface == "features"):
        fail("the importance is %s on a %s surface" % ("not 0" if surface == "flat" else "0 everywhere", surface))


def main():
    program, source, work, ratio, surface = sys.argv[1:6]
    extension = os.path.splitext(source)[1]
    os.makedirs(work, exist_ok=True)
    out = {name: os.path.join(work, name + extension) for name in ("direct", "lod", "kept")}
    runs = {"direct": [], "lod": ["--lod", "--importance", "--indices", os.path.join(work, "lod.txt")],
            "kept": ["--indices", os.path.join(work, "kept.txt")]}
    for name, options in runs.items():
        subprocess.run([program, source, out[name], "--ratio", ratio, "--quiet"] + options, check=True)
    order = [int(line) for line in open(os.path.join(work, "lod.txt"))]
    kept_order = [int(line) for line in open(os.path.join(work, "kept.txt"))]

    if extension == ".las":
        source_data, lod_data = open(source, "rb").read(), open(out["lod"], "rb").read()
        inputs, lod, direct = las_records(source_data), las_records(lod_data), las_records(open(out["direct"], "rb").read())
        n, m = len(inputs), len(direct)
        if sorted(order) != list(range(n)) or len(lod) != n:
            fail("lod.txt or the LOD file does not list every input record once")
        if any(lod[r][:-8] != inputs[order[r]] for r in range(n)):
            fail("a LOD record is not the input record lod.txt names, followed by 8 bytes")
        if sorted(r[:-8] for r in lod[:m]) != sorted(direct):
            fail("the first %d LOD records are not the direct run's" % m)
        descriptors = extra_bytes_descriptors(lod_data)
        if not descriptors or descriptors[-1][2] != 10 or descriptors[-1][4:36].split(b"\0")[0] != b"importance":
            fail("the Extra Bytes VLR does not end with the double 'importance'")
        h, written = las_layout(source_data), las_layout(lod_data)
        own_extra = h["length"] - BASE_SIZES[h["format"]]
        added = len(extra_bytes_descriptors(lod_data)) - len(extra_bytes_descriptors(source_data))
        new_vlr = not extra_bytes_descriptors(source_data)
        if written["length"] != h["length"] + 8 \
                or written["offset"] != h["offset"] + 192 * added + (54 if new_vlr else 0) \
                or written["vlrs"] != h["vlrs"] + (1 if new_vlr else 0):
            fail("the header's record length, offset to points or VLR count do not account for the attribute")
        if source_data[25] >= 4 and struct.unpack_from("<I", source_data, 243)[0]:
            if struct.unpack_from("<Q", lod_data, 235)[0] != written["offset"] + n * written["length"]:
                fail("the EVLR start is not the end of the LOD's points")
            if lod_data[written["offset"] + n * written["length"]:] != source_data[h["offset"] + n * h["length"]:]:
                fail("the EVLRs are not the input's")
        if sum(declared_size(d) for d in descriptors[:-1]) != own_extra:
            fail("the descriptors before 'importance' do not cover the records' own %d extra bytes" % own_extra)
        check_importance([struct.unpack("<d", r[-8:])[0] for r in lod], surface)
        print("LAS: %d records by rank, the first %d the direct run's, 'importance' after %d own extra bytes"
              % (n, m, own_extra))
    else:
        names, inputs = read_ply(source)
        lod_names, lod = read_ply(out["lod"])
        _, direct = read_ply(out["direct"])
        n, m = len(inputs), len(direct)
        if lod_names[:len(names)] != names or lod_names[len(names):] != ["scalar_rank", "scalar_importance"]:
            fail("the LOD file's properties are %s" % lod_names)
        if sorted(order) != list(range(n)) or len(lod) != n:
            fail("lod.txt or the LOD file does not list every input point once")
        if any(lod[r][:len(names)] != inputs[order[r]] for r in range(n)):
            fail("a LOD point is not the input point lod.txt names")
        if [row[len(names)] for row in lod] != list(range(n)):
            fail("scalar_rank does not count 0 to n - 1")
        if sorted(row[:len(names)] for row in lod[:m]) != sorted(direct):
            fail("the first %d LOD points are not the direct run's" % m)
        check_importance([row[-1] for row in lod], surface)
        print("PLY: %d points by rank, the first %d the direct run's, with scalar_rank and scalar_importance" % (n, m))

    if kept_order != order[:m]:
        fail("kept.txt is not the first %d lines of lod.txt" % m)
    if open(out["kept"], "rb").read() != open(out["direct"], "rb").read():
        fail("the output with --indices differs from the direct run's")
    print("kept.txt: the first %d by rank; the output with --indices is the direct run's" % m)


main()
