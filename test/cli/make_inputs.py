#!/usr/bin/env python3
"""Writes the small input files of the command-line tests (test/cli/inputs/)
and the seeds of the fuzzer's corpus (test/fuzz/corpus/). They are committed;
run this again only to change them. Each file is named for what it holds."""

import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
INPUTS = os.path.join(HERE, "inputs")
CORPUS = os.path.join(HERE, "..", "fuzz", "corpus")


def grid(n=12):
    """n*n points on a gently curved sheet: enough for k = 10."""
    return [(i * 0.1, j * 0.1, 0.05 * math.sin(i * 0.5) * math.cos(j * 0.4)) for i in range(n) for j in range(n)]


def write(name, data, folder=INPUTS):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def xyz_text(points):
    return "".join("%r %r %r\n" % p for p in points)


def ply_header(encoding, count, properties, extra=""):
    return ("ply\nformat %s 1.0\ncomment made by make_inputs.py\n%selement vertex %d\n" % (encoding, extra, count) +
            "".join("property %s %s\n" % (t, n) for t, n in properties) + "end_header\n")


def las(points, version=(1, 2), point_format=0, count=None, signature=b"LASF", scale=0.001, offset=(0., 0., 0.),
        vlr=b"", vlr_count=None, extra=0):
    """A LAS file of `points` (LAS 1.0-1.3 header layout, 227 or 235 bytes),
    with `extra` bytes after each record's own."""
    header_size = 235 if version >= (1, 3) else 227
    record_length = {0: 20, 1: 28, 2: 26, 3: 34}[point_format] + extra
    offset_to_points = header_size + len(vlr)
    n = len(points) if count is None else count
    xs = [p[0] for p in points] or [0.]
    ys = [p[1] for p in points] or [0.]
    zs = [p[2] for p in points] or [0.]
    h = bytearray(header_size)
    h[0:4] = signature
    h[24], h[25] = version
    h[26:58] = b"make_inputs.py".ljust(32, b"\0")
    h[58:90] = b"entropy_simplify tests".ljust(32, b"\0")
    vlrs = (1 if vlr else 0) if vlr_count is None else vlr_count
    struct.pack_into("<HHHIIBHI", h, 90, 1, 2026, header_size, offset_to_points, vlrs, point_format, record_length, n)
    struct.pack_into("<5I", h, 111, n, 0, 0, 0, 0)
    struct.pack_into("<3d3d", h, 131, scale, scale, scale, *offset)
    struct.pack_into("<6d", h, 179, max(xs) + offset[0], min(xs) + offset[0], max(ys) + offset[1],
                     min(ys) + offset[1], max(zs) + offset[2], min(zs) + offset[2])
    body = bytearray()
    for i, p in enumerate(points):
        r = bytearray(record_length)
        struct.pack_into("<3iHBBbBH", r, 0, *(round(c / scale) for c in p), 100 + i, 0x09, 2, 0, 0, 7)
        r[record_length - extra:] = bytes((i + b) % 256 for b in range(extra))
        body += r
    return bytes(h) + vlr + bytes(body)


def las14(points, point_format, vlrs=b"", evlr=b""):
    """A LAS 1.4 file of `points` in point format 6 or 10, with VLRs and one EVLR after the points."""
    record_length = {6: 30, 10: 67}[point_format]
    scale, offset_to_points = 0.001, 375 + len(vlrs)
    h = bytearray(375)
    h[0:4] = b"LASF"
    h[24], h[25] = 1, 4
    h[26:58] = b"make_inputs.py".ljust(32, b"\0")
    struct.pack_into("<HII", h, 94, 375, offset_to_points, vlrs.count(b"entropy_tests"))
    h[104] = point_format
    struct.pack_into("<H", h, 105, record_length)
    struct.pack_into("<3d3d", h, 131, scale, scale, scale, 500000., 4000000., 100.)
    body = bytearray()
    returns = [0] * 15
    for i, p in enumerate(points):
        r = bytearray(record_length)
        ret, n_ret = 1 + i % 3, 3
        returns[ret - 1] += 1
        struct.pack_into("<3iHBBBBhHd", r, 0, *(round(c / scale) for c in p), 1000 + i, ret | (n_ret << 4), 0x01,
                         6, 9, -300, 42, 1000.5 + i)
        if point_format == 10:
            struct.pack_into("<4H", r, 30, i, 2 * i, 3 * i, 4 * i)
        body += r
    xs, ys, zs = ([q[c] for q in points] for c in range(3))
    struct.pack_into("<6d", h, 179, max(xs) + 500000., min(xs) + 500000., max(ys) + 4000000., min(ys) + 4000000.,
                     max(zs) + 100., min(zs) + 100.)
    struct.pack_into("<QIQ15Q", h, 235, offset_to_points + len(body), 1 if evlr else 0, len(points), *returns)
    return bytes(h) + vlrs + bytes(body) + evlr


def evlr(user, record_id, payload):
    return struct.pack("<H16sHQ32s", 0, user, record_id, len(payload), b"an extended record") + payload


def vlr(user, record_id, payload):
    return struct.pack("<H16sHH32s", 0, user, record_id, len(payload), b"a test record") + payload


def extra_bytes_descriptor(data_type, name):
    """A descriptor of the Extra Bytes VLR (LAS 1.4 R15, 2.6): 192 bytes."""
    return struct.pack("<2sBB32s4s24s24s24s24s24s32s", b"", data_type, 0, name, b"", b"", b"", b"", b"", b"",
                       b"a test attribute")


def main():
    points = grid()
    # well-formed files in every input format
    write("grid.xyz", xyz_text(points))
    write("grid_crlf.xyz", xyz_text(points).replace("\n", "\r\n"))
    write("grid.off", "OFF\n%d 0 0\n" % len(points) + xyz_text(points))
    props = [("double", "x"), ("double", "y"), ("double", "z"), ("uchar", "red"), ("float", "intensity")]
    write("grid_ascii.ply", ply_header("ascii", len(points), props) +
          "".join("%r %r %r %d %r\n" % (p + (i % 256, i * 0.5)) for i, p in enumerate(points)))
    write("grid_binary.ply", ply_header("binary_little_endian", len(points), props).encode() +
          b"".join(struct.pack("<3dBf", *p, i % 256, i * 0.5) for i, p in enumerate(points)))
    write("grid_big_endian.ply", ply_header("binary_big_endian", len(points), props).encode() +
          b"".join(struct.pack(">3dBf", *p, i % 256, i * 0.5) for i, p in enumerate(points)))
    ints = [("int", "x"), ("int", "y"), ("int", "z")]
    write("integer_xyz_ascii.ply", ply_header("ascii", len(points), ints) +
          "".join("%d %d %d\n" % (round(p[0] * 100), round(p[1] * 100), round(p[2] * 100)) for p in points))
    write("integer_xyz_binary.ply", ply_header("binary_little_endian", len(points), ints).encode() +
          b"".join(struct.pack("<3i", round(p[0] * 100), round(p[1] * 100), round(p[2] * 100)) for p in points))
    write("grid.las", las(points, vlr=vlr(b"entropy_tests", 7, b"payload bytes")))
    write("grid_1_4_format_6.las", las14(points, 6, vlr(b"entropy_tests", 1, b"first VLR") +
                                         vlr(b"entropy_tests", 2, b"second VLR"),
                                         evlr(b"entropy_tests", 3, b"EVLR payload after the points")))
    write("grid_1_4_format_10.las", las14(points, 10, vlr(b"entropy_tests", 1, b"a VLR"),
                                          evlr(b"entropy_tests", 4, b"waveform-like EVLR payload")))
    # the same integer records, georeferenced: only the header's offsets differ
    write("grid_georeferenced.las", las(points, offset=(512345.67, 4123456.78, 250.), vlr=vlr(b"entropy_tests", 7,
                                                                                              b"payload bytes")))
    # extra bytes after the records' own: none declared, or 2 of 6 declared (a ushort)
    write("grid_undocumented_extra_bytes.las", las(points, extra=3, vlr=vlr(b"entropy_tests", 7, b"payload bytes")))
    write("grid_declared_extra_bytes.las",
          las(points, extra=6, vlr_count=2, vlr=vlr(b"entropy_tests", 7, b"payload bytes") +
              vlr(b"LASF_Spec", 4, extra_bytes_descriptor(3, b"strength"))))
    write("duplicates.xyz", "1 2 3\n" * 200)
    # an attribute 'importance' already declared; a reserved data type (40) of unknown size
    write("grid_with_importance.las", las(points, extra=8, vlr_count=1, vlr=vlr(b"LASF_Spec", 4,
                                                                                 extra_bytes_descriptor(10, b"importance"))))
    write("grid_reserved_extra_bytes_type.las", las(points, extra=4, vlr_count=1,
                                                    vlr=vlr(b"LASF_Spec", 4, extra_bytes_descriptor(40, b"unknown"))))
    # an Extra Bytes VLR declaring a double the records do not have
    write("grid_overdeclared_extra_bytes.las", las(points, vlr_count=1, vlr=vlr(b"LASF_Spec", 4,
                                                                                extra_bytes_descriptor(10, b"ghost"))))
    # two Extra Bytes VLRs, which LAS forbids (2 and 4 of the 6 extra bytes)
    write("grid_two_extra_bytes_vlrs.las",
          las(points, extra=6, vlr_count=2, vlr=vlr(b"LASF_Spec", 4, extra_bytes_descriptor(3, b"strength")) +
              vlr(b"LASF_Spec", 4, extra_bytes_descriptor(5, b"label"))))
    # LAS 1.3 whose waveform start (byte 227) points into its point records
    waveform_inside = bytearray(las(points, version=(1, 3)))
    struct.pack_into("<Q", waveform_inside, 227, 235 + 40)
    write("grid_waveform_start_inside_points.las", bytes(waveform_inside))
    # a PLY property named as --lod's ranks
    write("grid_with_rank.ply", ply_header("ascii", len(points), [("float", "x"), ("float", "y"), ("float", "z"),
                                                                  ("int", "scalar_rank")]) +
          "".join("%r %r %r %d\n" % (p + (7,)) for p in points))
    write("grid_cr.xyz", xyz_text(points).replace("\n", "\r"))

    # bad input: each file is one row of the table in doc/Entropy_simplification.txt
    write("empty.xyz", "")
    write("empty.ply", "")
    write("no_vertices.ply", ply_header("ascii", 0, props))
    write("no_xyz.ply", ply_header("ascii", 3, [("uchar", "red")]) + "1\n2\n3\n")
    write("huge_count_ascii.ply", ply_header("ascii", 4000000000, props) + "0 0 0 0 0\n")
    write("huge_count_binary.ply", ply_header("binary_little_endian", 4000000000, props).encode() + bytes(29))
    write("huge_list_count.ply", ("ply\nformat binary_little_endian 1.0\nelement face 1\n"
                                  "property list uint int vertex_indices\nelement vertex 1\n"
                                  "property float x\nproperty float y\nproperty float z\nend_header\n").encode() +
          struct.pack("<I", 4000000000) + bytes(16))
    write("truncated_binary.ply", ply_header("binary_little_endian", len(points), props).encode() +
          b"".join(struct.pack("<3dBf", *p, 0, 0.) for p in points[:len(points) // 2]))
    write("truncated.off", "OFF\n%d 0 0\n" % len(points) + xyz_text(points[:len(points) // 2]))
    write("not_a_ply.ply", "hello, world\n")
    write("unknown_ply_format.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 1\nproperty float x\n"
          "end_header\n")
    write("coff.off", "COFF\n1 0 0\n0 0 0 255 0 0 255\n")
    write("nan.xyz", xyz_text(points[:50]) + "0.5 nan 0.5\n" + xyz_text(points[50:]))
    write("inf.ply", ply_header("ascii", len(points), ints[:0] + [("float", "x"), ("float", "y"), ("float", "z")]) +
          "".join("%r %r %r\n" % p for p in points[:-1]) + "inf 0 0\n")
    write("huge_coordinate.xyz", xyz_text(points) + "1e155 0 0\n")
    write("tiny_extent.xyz", xyz_text([(x * 1e-200, y * 1e-200, z * 1e-200) for x, y, z in points]))
    write("too_near.xyz", xyz_text(points + [(x * 1e-200, y * 1e-200, z * 1e-200) for x, y, z in points]))
    write("byte_order_mark.xyz", b"\xef\xbb\xbf" + xyz_text(points).encode())
    write("words.xyz", "hello world and more\n")
    write("mixed_widths.xyz", xyz_text(points[:10]) + "0 0 0 0 0 1\n")
    write("triangle_soup.xyz", "0 0 0 1 0 0 0 1 0\n" * 20)
    write("too_few_points.xyz", xyz_text(points[:5]))
    write("coincident_group.xyz", xyz_text(points) + "0.5 0.5 0.5\n" * 5001)
    write("las_offset_beyond_1e150.las", las(points, offset=(1e200, 0., 0.)))
    write("bad_signature.las", las(points, signature=b"LASX"))
    write("truncated_header.las", las(points)[:100])
    write("las_version_2.las", las(points, version=(2, 0)))
    write("las_count_beyond_file.las", las(points, count=100000))
    write("las_count_short.las", las(points, count=100))
    compressed = bytearray(las(points))
    compressed[104] |= 0x80
    write("laz_in_las.las", bytes(compressed))

    # seeds of the fuzzer's corpus: one small valid file per reader, its first byte naming the reader
    for name in ("grid.xyz", "grid.off", "grid_ascii.ply", "grid_binary.ply", "grid_big_endian.ply",
                 "integer_xyz_binary.ply", "grid.las", "grid_1_4_format_6.las", "grid_1_4_format_10.las",
                 "huge_list_count.ply"):
        with open(os.path.join(INPUTS, name), "rb") as f:
            data = f.read()
        kind = {"xyz": b"x", "off": b"o", "ply": b"p", "las": b"l"}[name.rsplit(".", 1)[1]]
        write(name.replace(".", "_"), kind + data[:4000], CORPUS)


if __name__ == "__main__":
    main()
