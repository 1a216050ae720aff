"""The Python module against the C++ program (entropy_simplify, which calls
the library without the module's code): the same points, ranks, importance
and report, in both modes; NumPy inputs of every layout; bad input; Ctrl-C;
and the Open3D example. Run by CTest, which sets PYTHONPATH to the module,
ES_PROGRAM to the program, ES_DATA_DIR to CGAL's demo data and ES_EXAMPLES_DIR
to examples/python."""

import collections
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import entropy_simplification as es

PROGRAM = os.environ["ES_PROGRAM"]
DATA = os.environ["ES_DATA_DIR"]


@pytest.fixture(scope="module")
def kitten():
    """CGAL's kitten scan (5,210 points), x y z only."""
    return np.loadtxt(os.path.join(DATA, "points_3", "kitten.xyz"))[:, :3].copy()


def write_xyz(path, points):
    # repr() writes the shortest text that reads back as the same double
    with open(path, "w") as f:
        for p in points:
            f.write("%r %r %r\n" % (float(p[0]), float(p[1]), float(p[2])))


def run_program(*args):
    return subprocess.run([PROGRAM] + [str(a) for a in args], check=True, capture_output=True, text=True).stdout


def read_binary_ply(path):
    """The vertices of a binary little-endian PLY as a NumPy structured array."""
    types = {"double": "<f8", "float": "<f4", "uint": "<u4", "int": "<i4", "uchar": "u1"}
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    fields, count = [], 0
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            fields.append((words[2], types[words[1]]))
    return np.frombuffer(data, dtype=np.dtype(fields), count=count, offset=end)


@pytest.mark.parametrize("mode", ["default", "paper"])
@pytest.mark.parametrize("target", [("--ratio", 0.1), ("--count", 300)])
def test_simplify_equals_the_program(kitten, tmp_path, mode, target):
    write_xyz(tmp_path / "in.xyz", kitten)
    run_program(tmp_path / "in.xyz", tmp_path / "out.xyz", target[0], target[1], "--mode", mode,
                "--indices", tmp_path / "kept.txt", "--quiet")
    expected = np.loadtxt(tmp_path / "kept.txt", dtype=np.int64)
    keyword = {"--ratio": "ratio", "--count": "count"}[target[0]]
    kept = es.simplify(kitten, mode=mode, **{keyword: target[1]})
    assert kept.dtype == np.int64
    np.testing.assert_array_equal(kept, expected)
    # the kept points are the program's output, which lists them in input order
    np.testing.assert_array_equal(kitten[np.sort(kept)], np.loadtxt(tmp_path / "out.xyz"))


@pytest.mark.parametrize("mode", ["default", "paper"])
def test_ranks_and_importance_equal_the_program(kitten, tmp_path, mode):
    write_xyz(tmp_path / "in.xyz", kitten)
    run_program(tmp_path / "in.xyz", tmp_path / "lod.ply", "--lod", "--ratio", 0.05, "--mode", mode, "--importance",
                "--indices", tmp_path / "lod.txt", "--quiet")
    order = np.loadtxt(tmp_path / "lod.txt", dtype=np.int64)
    ranks = es.ranks(kitten, ratio=0.05, mode=mode)
    assert sorted(ranks.tolist()) == list(range(len(kitten)))
    np.testing.assert_array_equal(np.argsort(ranks), order)
    written = read_binary_ply(tmp_path / "lod.ply")
    np.testing.assert_array_equal(written["scalar_rank"], np.arange(len(kitten)))
    np.testing.assert_array_equal(written["scalar_importance"], es.importance(kitten, mode=mode)[order])


def test_report_equals_the_program(kitten, tmp_path):
    write_xyz(tmp_path / "in.xyz", kitten)
    printed = run_program(tmp_path / "in.xyz", tmp_path / "out.xyz", "--ratio", 0.1, "--report", "--quiet")
    report = es.report(kitten, es.simplify(kitten, ratio=0.1))
    assert report["input_size"] == len(kitten) and report["kept_size"] == 521
    for name, key in (("mean distance", "mean_distance"), ("max distance", "max_distance"),
                      ("point-to-plane", "point_to_plane")):
        value = float(re.search(name + r" +([0-9.e+-]+)", printed).group(1))
        assert report[key] == pytest.approx(value, rel=1e-5)  # the program prints 6 digits


def test_paper_mode_prefixes_are_direct_calls(kitten):
    order = np.argsort(es.ranks(kitten, mode="paper"))
    for m in (11, 100, 2605):
        np.testing.assert_array_equal(es.simplify(kitten, count=m, mode="paper"), order[:m])


def test_any_layout_and_float32(kitten):
    expected = es.simplify(kitten, count=400)
    # a memoryview is a sequence too, but of numbers: no rows to check
    for view in (np.asfortranarray(kitten), np.ascontiguousarray(kitten.T).T,
                 np.hstack([kitten, kitten])[:, :3], kitten.tolist(), memoryview(np.ascontiguousarray(kitten))):
        np.testing.assert_array_equal(es.simplify(view, count=400), expected)
    single = kitten.astype(np.float32)
    np.testing.assert_array_equal(es.simplify(single, count=400), es.simplify(single.astype(np.float64), count=400))
    strided = kitten[::2]
    np.testing.assert_array_equal(es.simplify(strided, count=100), es.simplify(strided.copy(), count=100))


def test_options_and_threads(kitten):
    expected = es.simplify(kitten, ratio=0.1)
    # a float32 ratio is the decimal it prints as: float32's 0.1 lies above
    # 0.1 and, read as it is, kept one point more
    np.testing.assert_array_equal(es.simplify(kitten, ratio=np.float32(0.1)), expected)
    np.testing.assert_array_equal(es.simplify(kitten, ratio=np.float16(0.1)), expected)
    np.testing.assert_array_equal(es.simplify(kitten, ratio=np.array(0.1, dtype=np.float32)), expected)
    # any count up to 2**64 - 1, as the program's --count: all of the points
    everything = es.simplify(kitten, count=len(kitten))
    np.testing.assert_array_equal(es.simplify(kitten, count=2 ** 64 - 1), everything)
    np.testing.assert_array_equal(es.simplify(kitten, count=np.uint64(2 ** 64 - 1)), everything)
    # a masked array with nothing masked is its data
    np.testing.assert_array_equal(es.simplify(np.ma.masked_array(kitten), ratio=0.1), expected)
    # and a list of masked rows with nothing masked, their values, whether
    # their masks are none or arrays of False
    np.testing.assert_array_equal(es.simplify(list(np.ma.masked_array(kitten)), ratio=0.1), expected)
    unmasked = np.ma.masked_array(kitten, mask=np.zeros(kitten.shape, bool))
    np.testing.assert_array_equal(es.simplify(list(unmasked), ratio=0.1), expected)
    np.testing.assert_array_equal(es.simplify(kitten, count=np.int64(521), k=np.int32(10)), expected)
    np.testing.assert_array_equal(es.simplify(kitten, ratio=0.1, threads=1), expected)
    # more threads than the machine runs: as many as it runs (TBB would
    # otherwise reserve memory for each, 1.3 GB for 10**7)
    np.testing.assert_array_equal(es.simplify(kitten, ratio=0.1, threads=2 ** 31 - 1), expected)
    kept = es.simplify(kitten, ratio=0.1)
    assert es.report(kitten, kept.astype(np.uint32)) == es.report(kitten, kept)
    jet = es.simplify(kitten, ratio=0.1, normals="jet", k=12, feature_weight=1.0)
    assert len(jet) == len(expected) and not np.array_equal(jet, expected)
    highest = es.simplify(kitten, ratio=0.1, mode="paper", order="highest")
    assert len(np.unique(highest)) == len(expected)
    importance = es.importance(kitten)
    assert importance.dtype == np.float64 and importance.min() >= 0. and 0. < importance.max() <= 1.
    paper = es.importance(kitten, mode="paper", k=10)
    assert paper.min() >= 0. and paper.max() <= np.log(11.) + 1e-12


def test_empty_input():
    assert len(es.simplify(np.zeros((0, 3)), count=5)) == 0
    assert len(es.ranks(np.zeros((0, 3)))) == 0
    assert len(es.importance(np.zeros((0, 3)))) == 0


@pytest.mark.parametrize("call, message", [
    (lambda p: es.simplify(p), "give one of ratio and count"),
    (lambda p: es.simplify(p, ratio=0.1, count=5), "only one of ratio and count"),
    (lambda p: es.simplify(p, ratio=1.5), r"ratio must lie in \(0, 1\]"),
    (lambda p: es.simplify(p, count=0), "count must be at least 1"),
    (lambda p: es.simplify(p, count=10, k=1), "k = 1 is out of range"),
    (lambda p: es.simplify(p, count=10, k=4, normals="jet"), "k = 4 is out of range"),
    (lambda p: es.simplify(p, count=10, mode="fast"), "mode must be 'default' or 'paper'"),
    (lambda p: es.simplify(p, count=10, normals="svd"), "normals must be 'pca' or 'jet'"),
    (lambda p: es.simplify(p, count=10, order="lowest"), "order applies to mode='paper' only"),
    (lambda p: es.simplify(p, count=10, mode="paper", feature_weight=2.), "feature_weight applies to the default"),
    (lambda p: es.simplify(p, count=10, feature_weight=-1.), "feature_weight must lie in \\[0, 100\\]"),
    (lambda p: es.simplify(p, count=5, mode="paper"), "must keep at least k \\+ 1 = 11 points"),
    (lambda p: es.simplify(p, count=10, threads=0), "threads must be at least 1"),
    (lambda p: es.simplify(p[:, :2], count=10), r"points must be an \(n, 3\) array"),
    (lambda p: es.simplify(p[:8], count=5), "needs at least k \\+ 1 distinct points"),
    (lambda p: es.simplify(np.where(np.arange(len(p))[:, None] == 7, np.nan, p), count=10),
     "point #7 has a coordinate that is not finite"),
    (lambda p: es.simplify(p * 1e-200, count=10), "which is not 0 but below 1e-150"),
    (lambda p: es.simplify(np.vstack([p, p * 1e-200]), count=10), "closer than about 1.5e-154"),
    (lambda p: es.simplify(p, ratio="a tenth"), "ratio must be a number, got 'a tenth'"),
    (lambda p: es.simplify(p, count=2.5), "count must be a whole number, got 2.5"),
    (lambda p: es.simplify(p, count=2 ** 70), "count is out of range"),
    (lambda p: es.simplify(p, count=2 ** 64), "count is out of range, got 18446744073709551616"),
    (lambda p: es.simplify(p, count=-2 ** 70), "count must be at least 1"),
    (lambda p: es.simplify(p.astype(complex), count=10), "points must hold real numbers, not values of dtype complex128"),
    (lambda p: es.simplify(p.astype(str), count=10), "points must hold real numbers, not values of dtype <U"),
    (lambda p: es.importance(p > 0.), "points must hold real numbers, not values of dtype bool"),
    (lambda p: es.ranks(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7)),
     "points is a masked array with masked values"),
    (lambda p: es.report(p, np.ma.masked_array(np.arange(10), mask=np.arange(10) == 9)),
     r"kept_idx is a masked array with masked values: pass kept_idx.compressed\(\)"),
    # the same through a list or an object NumPy reads (__array__)
    (lambda p: es.report((p > 0.).tolist(), [0, 1, 2]), "points must hold real numbers, not values of dtype bool"),
    (lambda p: es.simplify([[repr(v) for v in row] for row in p], count=10), "not values of dtype <U"),
    (lambda p: es.simplify(p.astype(object), count=10), "not values of dtype object"),
    (lambda p: es.simplify(Reads_as(p + 5j), count=10), "not values of dtype complex128"),
    (lambda p: es.simplify(Reads_as(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7)), count=10),
     "points is a masked array with masked values"),
    (lambda p: es.report(p, Reads_as(np.ma.masked_array(np.arange(10), mask=np.arange(10) == 9))), "masked values"),
    # a list of masked rows, which NumPy reads without the masks
    (lambda p: es.simplify(list(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7)), count=10),
     r"points is a list of masked rows with masked values: pass the rows to keep, as m\[~m.mask.any\(axis=1\)\]"),
    (lambda p: es.report(tuple(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7)), [0, 1, 2]),
     "points is a list of masked rows with masked values"),
    (lambda p: es.importance(collections.deque(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7))),
     "points is a list of masked rows with masked values"),
    # a list of masked blocks of rows: its shape is what is wrong
    (lambda p: es.simplify(list(np.ma.masked_array(p, mask=np.arange(p.size).reshape(p.shape) == 7).reshape(-1, 1, 3)),
                           count=10), r"points must be an \(n, 3\) array"),
    # one real number, not an array of them or a complex one
    (lambda p: es.simplify(p, ratio=np.array([0.1])), r"ratio must be a number, got array\(\[0.1\]\)"),
    (lambda p: es.simplify(p, ratio=np.complex64(0.1 + 0.7j)), "ratio must be a number"),
    (lambda p: es.simplify(p, count=np.array([5])), r"count must be a whole number, got array\(\[5\]\)"),
    (lambda p: es.simplify(p, count=Index_of("5")), "count must be a whole number"),
    (lambda p: es.simplify(p, count=10, k="ten"), "k must be a whole number"),
    (lambda p: es.simplify(p, count=10, threads=True), "threads must be a whole number"),
    (lambda p: es.report(p, np.array([0, len(p)])), "not an index of the"),
    (lambda p: es.report(p, np.array([], dtype=np.int64)), "the simplification is empty"),
    (lambda p: es.report(p, np.arange(len(p)) % 10 == 0), r"kept_idx must hold integers, not values of dtype "
     r"bool \(for a mask of kept points, pass numpy.flatnonzero\(mask\)\)"),
    (lambda p: es.report(p, np.array([2.7, 5.2])), "kept_idx must hold integers, not values of dtype float64"),
    (lambda p: es.report(p, np.array([2 ** 64 - 1], dtype=np.uint64)),
     "kept_idx holds 18446744073709551615, not an index of the"),
    (lambda p: es.report(p, np.array([], dtype="i8,i8")), "the simplification is empty"),
    (lambda p: es.report(p, np.array([3, 5, 3])), "kept_idx holds the index 3 more than once"),
    (lambda p: es.simplify(p, count=10, mode=None), "mode must be a string, got None"),
    (lambda p: es.simplify(p, count=10, normals=b"pca"), "normals must be a string, got b'pca'"),
    (lambda p: es.simplify(p, count=20, mode="paper", order=1), "order must be a string, got 1"),
    (lambda p: es.simplify(p, ratio=np.bool_(True)), "ratio must be a number, got True"),
    (lambda p: es.simplify(p, count=np.bool_(True)), "count must be a whole number, got True"),
])
def test_bad_input_raises_value_error(kitten, call, message):
    with pytest.raises(ValueError, match=message):
        call(kitten)


class Reads_as:
    """An object NumPy reads as the array it holds."""

    def __init__(self, array):
        self.array = array

    def __array__(self, dtype=None, copy=None):
        return self.array


class Index_of:
    """An object whose __index__ gives what it holds."""

    def __init__(self, value):
        self.value = value

    def __index__(self):
        return self.value


class Interrupting:
    """Raises KeyboardInterrupt when NumPy or the module converts it."""

    def __array__(self, dtype=None, copy=None):
        raise KeyboardInterrupt

    def __float__(self):
        raise KeyboardInterrupt

    def __index__(self):
        raise KeyboardInterrupt


@pytest.mark.parametrize("call", [
    lambda p: es.simplify(Interrupting(), ratio=0.5),
    lambda p: es.simplify(p, ratio=Interrupting()),
    lambda p: es.simplify(p, count=Interrupting()),
    lambda p: es.report(p, Interrupting()),
])
def test_an_interruption_during_a_conversion_stays_one(kitten, call):
    """Ctrl-C while an argument is converted is not reported as bad input."""
    with pytest.raises(KeyboardInterrupt):
        call(kitten)


def test_the_gil_is_released():
    """A Python thread runs while the module computes."""
    points = np.random.default_rng(2).random((200000, 3))
    ticks, stop = [], threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    time.sleep(0.05)
    before = len(ticks)
    es.simplify(points, ratio=0.1)
    during = len(ticks) - before
    stop.set()
    ticker.join()
    assert during > 10


def test_ctrl_c_raises_keyboard_interrupt():
    """SIGINT during a long call: KeyboardInterrupt, not the call's end."""
    script = ("import sys, numpy as np, entropy_simplification as es\n"
              "points = np.random.default_rng(1).random((400000, 3))\n"
              "print('started', flush=True)\n"
              "try:\n"
              "    es.simplify(points, ratio=0.01, mode='paper')\n"
              "    print('finished')\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted')\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.)
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=120)
    assert out.strip() == "interrupted"


def test_open3d_example(tmp_path):
    pytest.importorskip("open3d")
    example = os.path.join(os.environ["ES_EXAMPLES_DIR"], "open3d_example.py")
    output = tmp_path / "simplified.ply"
    printed = subprocess.run([sys.executable, example, os.path.join(DATA, "points_3", "b9_training.ply"), output],
                             check=True, capture_output=True, text=True).stdout
    assert "kept 2230 of 22300 points" in printed
    import open3d as o3d
    assert len(o3d.io.read_point_cloud(str(output)).points) == 2230
