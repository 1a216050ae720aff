#!/usr/bin/env python3
"""check_las_round_trip.py PROGRAM INPUT.las WORK [ARGS...]: runs
`PROGRAM INPUT.las WORK/out.las ARGS` and checks the output against the input
with a reader of its own, written from the LAS specification and sharing no
code with the program:
- the kept records are records of the input, byte for byte, in input order;
- the header and the VLRs are the input's bytes, but for the point counts
  (legacy and 1.4, by return), the bounds and the EVLR and waveform offsets,
  which must be those of the kept records;
- every byte after the point data (EVLRs) is the input's.
Prints what it checked; exits 1 on the first difference."""

import struct
import subprocess
import sys


def header(data):
    h = {"minor": data[25], "header_size": struct.unpack_from("<H", data, 94)[0]}
    h["offset"], h["vlrs"] = struct.unpack_from("<II", data, 96)
    h["format"], h["length"] = data[104], struct.unpack_from("<H", data, 105)[0]
    h["legacy_count"] = struct.unpack_from("<I", data, 107)[0]
    h["legacy_by_return"] = list(struct.unpack_from("<5I", data, 111))
    h["scale"], h["origin"] = struct.unpack_from("<3d", data, 131), struct.unpack_from("<3d", data, 155)
    h["bounds"] = struct.unpack_from("<6d", data, 179)
    h["count"] = h["legacy_count"]
    h["waveform"] = struct.unpack_from("<Q", data, 227)[0] if h["minor"] >= 3 else 0
    if h["minor"] >= 4:
        h["evlr_start"], h["evlrs"], count = struct.unpack_from("<QIQ", data, 235)
        h["by_return"] = list(struct.unpack_from("<15Q", data, 255))
        h["count"] = count or h["count"]
    return h


def records(data, h):
    return [data[h["offset"] + i * h["length"]:h["offset"] + (i + 1) * h["length"]] for i in range(h["count"])]


# the header's fields the program rewrites, as (start, end) byte ranges
def patched_ranges(h):
    ranges = [(107, 131), (179, 227)]
    if h["minor"] >= 3:
        ranges.append((227, 235))
    if h["minor"] >= 4:
        ranges += [(235, 243), (247, 375)]
    return ranges


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def main():
    program, source, work, args = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    target = work + "/out.las"
    subprocess.run(["mkdir", "-p", work], check=True)
    subprocess.run([program, source, target, "--quiet"] + args, check=True)
    data_in, data_out = open(source, "rb").read(), open(target, "rb").read()
    h_in, h_out = header(data_in), header(data_out)

    # the kept records: a subsequence of the input's records
    kept, position = records(data_out, h_out), 0
    originals = records(data_in, h_in)
    for k, record in enumerate(kept):
        while position < len(originals) and originals[position] != record:
            position += 1
        if position == len(originals):
            fail("kept record %d is not an input record after the previous one" % k)
        position += 1

    # the header and VLRs, but for the patched fields
    same = bytearray(data_in[:h_in["offset"]])
    other = bytearray(data_out[:h_out["offset"]])
    for start, end in patched_ranges(h_in):
        same[start:end] = other[start:end] = bytes(end - start)
    if same != other:
        fail("the header or the VLRs differ outside the point counts, bounds and offsets")

    # the counts, by return, and the bounds, of the kept records
    mask = 0x0f if h_in["format"] >= 6 else 0x07
    by_return = [0] * 16
    for record in kept:
        by_return[record[14] & mask] += 1
    if h_out["count"] != len(kept):
        fail("point count %d, kept %d" % (h_out["count"], len(kept)))
    legacy = h_in["format"] < 6
    if h_out["legacy_count"] != (len(kept) if legacy else 0) or \
            h_out["legacy_by_return"] != (by_return[1:6] if legacy else [0] * 5):
        fail("legacy counts %d %s, expected %s" % (h_out["legacy_count"], h_out["legacy_by_return"], by_return[1:6]))
    if h_in["minor"] >= 4 and h_out["by_return"] != by_return[1:16]:
        fail("1.4 counts by return %s, expected %s" % (h_out["by_return"], by_return[1:16]))
    xyz = [[struct.unpack_from("<i", r, 4 * c)[0] * h_in["scale"][c] + h_in["origin"][c] for r in kept]
           for c in range(3)]
    bounds = (max(xyz[0]), min(xyz[0]), max(xyz[1]), min(xyz[1]), max(xyz[2]), min(xyz[2]))
    if h_out["bounds"] != bounds:
        fail("bounds %s, expected %s" % (h_out["bounds"], bounds))

    # everything after the points, and the offsets into it
    end_in = h_in["offset"] + h_in["count"] * h_in["length"]
    end_out = h_out["offset"] + len(kept) * h_out["length"]
    if data_out[end_out:] != data_in[end_in:]:
        fail("the bytes after the point data differ")
    if h_in["minor"] >= 4 and h_in["evlrs"] and h_out["evlr_start"] != h_in["evlr_start"] - end_in + end_out:
        fail("the EVLR offset was not moved with the point data")
    print("%s: %d of %d records kept byte for byte, in order; header and %d VLRs (%d bytes) as the input's; "
          "counts by return %s and bounds correct; %d bytes after the points (EVLRs: %d) identical"
          % (source.rsplit("/", 1)[-1], len(kept), len(originals), h_in["vlrs"], h_in["offset"] - h_in["header_size"],
             by_return[1:6] if legacy else by_return[1:16], len(data_in) - end_in, h_in.get("evlrs", 0)))


if __name__ == "__main__":
    main()
