#!/usr/bin/env python3
# Test machinery: not part of any assignment.
# Writes the hostile films that `bin/pathtracer --merge` must refuse (tests/framework/test_film.c runs
# them), and two good ones it must accept, into the folder given:
#
#   python3 tests/data/make_hostile_films.py DIR
#
# Each file is an OpenEXR film written byte by byte here (the standard library only: struct and
# zlib), in the layout framework/exr.c writes: one scanline part, ZIP, the 41 channels, the five
# pathlab.* string attributes. Each hostile one changes one thing. DIR/manifest.txt lists one merge a
# line: "expected words|file [file...]" ("ok" for a merge that must succeed), for the test to run.
import os
import struct
import sys
import zlib

LETTERS = "RGBY"
CHANNELS = sorted(["R", "G", "B"] + ["var." + c for c in LETTERS] + ["n", "bad"] +
                  ["acc.%s.%s.%d" % (k, c, w) for k in ("sum", "sq") for c in LETTERS for w in range(4)])
FLOAT = {"R", "G", "B"} | {"var." + c for c in LETTERS}
GOOD_ATTRS = {"pathlab.command": b"pathtracer -s 2 -l 1 -m 1 -o 1 -b 0 -d 4.7 -r 4 3 --seed 7 --leaf-size 4 "
                                 b"scenes/cornell_spheres.dae",
              "pathlab.seed": b"7", "pathlab.version": b"hostile-1", "pathlab.samples": b"0:2 of 2",
              "pathlab.render_key": b"0123456789abcdef"}


def attr(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def chlist(types, sampling):
    out = b""
    for name in sorted(types):
        xs, ys = sampling.get(name, (1, 1))
        out += name.encode() + b"\0" + struct.pack("<iB3xii", types[name], 0, xs, ys)
    return out + b"\0"


def zip_chunk(raw):
    """OpenEXR's ZIP: bytes split into even and odd halves, delta-coded, deflated; raw when not smaller."""
    t = raw[0::2] + raw[1::2]
    d = bytes([t[0]] + [(t[i] - t[i - 1] + 384) & 0xFF for i in range(1, len(t))]) if t else b""
    packed = zlib.compress(d, 6)
    return packed if len(packed) < len(raw) else raw


def pixel_words(p):
    """The 32 bits of every channel of one pixel (p: n, bad, sum[4], sq[4] as integers)."""
    words = {"n": p["n"], "bad": p["bad"]}
    for c in range(4):
        for w in range(4):
            words["acc.sum.%s.%d" % (LETTERS[c], w)] = (p["sum"][c] >> (32 * w)) & 0xFFFFFFFF
            words["acc.sq.%s.%d" % (LETTERS[c], w)] = (p["sq"][c] >> (32 * w)) & 0xFFFFFFFF
    return words


def film(path, width=4, height=3, attrs=None, pixel=None, types=None, sampling=None, compression=3,
         window=None, display=None, version_flags=2, cut=None, chunk_hook=None, drop=None, extra=None):
    """Writes one film; every argument left out is what pathlab writes (a black 0:2 of 2 render)."""
    attrs = dict(GOOD_ATTRS, **(attrs or {}))
    types = dict(types or {name: 2 if name in FLOAT else 0 for name in CHANNELS})
    for name in drop or []:
        del types[name]
    types.update(extra or {})
    pixel = pixel or (lambda x, y: {"n": 2, "bad": 0, "sum": [0] * 4, "sq": [0] * 4})
    window = window or (0, 0, width - 1, height - 1)
    header = attr("channels", "chlist", chlist(types, sampling or {}))
    header += attr("compression", "compression", bytes([compression]))
    header += attr("dataWindow", "box2i", struct.pack("<4i", *window))
    header += attr("displayWindow", "box2i", struct.pack("<4i", *(display or window)))
    header += attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1))
    header += attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
    header += attr("screenWindowWidth", "float", struct.pack("<f", 1))
    for name, value in attrs.items():
        if value is not None:
            header += attr(name, "string", value) if isinstance(value, bytes) else attr(name, value[0], value[1])
    lines = 16 if compression == 3 else 1
    chunks = []
    for y0 in range(0, height, lines):
        raw = b""
        for y in range(y0, min(y0 + lines, height)):
            words = [pixel_words(pixel(x, y)) for x in range(width)]
            for name in sorted(types):
                raw += b"".join(struct.pack("<I", w.get(name, 0)) for w in words)
        data = zip_chunk(raw) if compression == 3 else raw
        chunks.append(chunk_hook(y0, raw, data) if chunk_hook else struct.pack("<ii", y0, len(data)) + data)
    head = b"\x76\x2f\x31\x01" + struct.pack("<I", version_flags) + header + b"\0"
    offset, table = len(head) + 8 * len(chunks), b""
    for c in chunks:
        table += struct.pack("<Q", offset)
        offset += len(c)
    data = head + table + b"".join(chunks)
    with open(path, "wb") as f:
        f.write(data[:cut] if cut else data)


def main(out):
    os.makedirs(out, exist_ok=True)
    manifest = []

    def case(expect, name, **kw):
        film(os.path.join(out, name), **kw)
        manifest.append((expect, [name]))

    def pixel(n=2, bad=0, s=0, q=0):
        return lambda x, y: {"n": n, "bad": bad, "sum": [s] * 4, "sq": [q] * 4}

    # The controls: what pathlab writes is accepted, alone and as two ranges of one render.
    case("ok", "good.exr")
    film(os.path.join(out, "range0.exr"), attrs={"pathlab.samples": b"0:1 of 2"}, pixel=pixel(n=1))
    film(os.path.join(out, "range1.exr"), attrs={"pathlab.samples": b"1:2 of 2"}, pixel=pixel(n=1))
    manifest.append(("ok", ["range0.exr", "range1.exr"]))

    # Layout: subsampled (the uninitialised read), missing, foreign, mistyped channels; compression;
    # storage; windows and the size cap (a 2.6 MB file declaring 4096x4096 cost 2.7 GB before).
    case("channel n: sampling 2x1", "subsampled.exr", sampling={"n": (2, 1)})
    case("channel acc.sum.R.0: sampling 1x2", "subsampled_y.exr", height=4, sampling={"acc.sum.R.0": (1, 2)})
    case("channels: expected the 41", "missing_channel.exr", drop=["bad"])
    case("channel 'Z'", "foreign_channel.exr", drop=["bad"], extra={"Z": 2})
    case("channel n: expected type uint", "float_count.exr", types={**{c: 0 for c in CHANNELS}, **{c: 2 for c in FLOAT}, "n": 2})
    case("channel R: expected type float", "half_mean.exr", types={**{c: 0 for c in CHANNELS}, **{c: 2 for c in FLOAT}, "R": 1})
    case("compression: expected ZIP", "uncompressed.exr", compression=0)
    case("compression: expected ZIP", "piz.exr", compression=4)
    case("tiled_flag.exr: cannot read as OpenEXR", "tiled_flag.exr", version_flags=2 | 0x200)
    case("dataWindow", "huge.exr", window=(0, 0, 4095, 4095))
    case("dataWindow", "wide.exr", window=(0, 0, 70000, 0))
    case("dataWindow", "negative_origin.exr", window=(-1, 0, 3, 2))
    case("dataWindow", "display_differs.exr", display=(0, 0, 7, 7))
    # Attributes: each parsed to the writer's form.
    for i, (field, value, words) in enumerate([
            ("pathlab.seed", b"-1", "pathlab.seed"), ("pathlab.seed", b"18446744073709551616", "pathlab.seed"),
            ("pathlab.seed", b"07", "pathlab.seed"), ("pathlab.seed", b"", "pathlab.seed"),
            ("pathlab.samples", b"2:1 of 2", "pathlab.samples"), ("pathlab.samples", b"0:3 of 2", "pathlab.samples"),
            ("pathlab.samples", b"0:4294967298 of 4294967298", "pathlab.samples"),
            ("pathlab.samples", b"-1:2 of 2", "pathlab.samples"), ("pathlab.samples", b"0:2 of 2 ", "pathlab.samples"),
            ("pathlab.samples", b"0:2 of 99999999", "pathlab.samples"),
            ("pathlab.render_key", b"0123456789ABCDEF", "pathlab.render_key"),
            ("pathlab.render_key", b"0123456789abcdeg", "pathlab.render_key"),
            ("pathlab.render_key", b"0123456789abcde", "pathlab.render_key"),
            ("pathlab.command", b"rm -rf / scene.dae", "pathlab.command"),
            ("pathlab.command", b"pathtracer \xff\xfe scene.dae", "pathlab.command: expected UTF-8"),
            ("pathlab.command", b"pathtracer \x1b[2J scene.dae", "pathlab.command: expected UTF-8"),
            ("pathlab.version", None, "pathlab.version"),
            ("pathlab.seed", ("int", struct.pack("<i", 7)), "pathlab.seed")]):
        case(words, "attribute%02d.exr" % i, attrs={field: value})
    # Numbers: every pixel must be one its range could give.
    case("n = 4 samples, expected 2", "count_above_range.exr", pixel=pixel(n=4))
    case("n = 4294967295 samples", "count_wraps.exr", pixel=pixel(n=4294967295))
    case("bad = 3, more than", "bad_above_count.exr", pixel=pixel(bad=3))
    case("sums without a good sample", "sums_without_samples.exr", pixel=pixel(bad=2, s=5, q=5))
    case("a sum above good samples", "sum_too_large.exr", pixel=pixel(s=1 << 100, q=1 << 120))
    case("a sum too large for its sum of squares", "sum_without_squares.exr", pixel=pixel(s=1 << 40, q=0))
    case("a sum of squares above", "squares_too_large.exr", pixel=pixel(q=1 << 127))
    # Chunks: cut short, lying about their size or row, or inflating beyond their rows.
    film(os.path.join(out, "whole.exr"), width=64, height=40)
    size = os.path.getsize(os.path.join(out, "whole.exr"))
    case("chunk", "truncated.exr", width=64, height=40, cut=size - 200)
    case("header_only.exr: cannot read as OpenEXR", "header_only.exr", width=64, height=40, cut=size // 4)
    case("the chunk at row 0", "chunk_claims_more.exr",
         chunk_hook=lambda y0, raw, data: struct.pack("<ii", y0, len(data) + 1000000) + data)
    case("the chunk at row 0", "chunk_wrong_row.exr",
         chunk_hook=lambda y0, raw, data: struct.pack("<ii", y0 + 5, len(data)) + data)
    bomb = zlib.compress(b"\0" * (1 << 24), 9)
    case("the chunk at row 0", "zip_bomb.exr", chunk_hook=lambda y0, raw, data: struct.pack("<ii", y0, len(bomb)) + bomb)
    case("cannot read as OpenEXR", "not_exr.exr", version_flags=0, cut=3)

    # Merges: pieces of different renders (each provenance field named), and counts that would wrap.
    def pair(expect, name, attrs, **kw):
        film(os.path.join(out, name + "_a.exr"), attrs={"pathlab.samples": b"0:1 of 2"}, pixel=pixel(n=1))
        film(os.path.join(out, name + "_b.exr"), attrs=dict({"pathlab.samples": b"1:2 of 2"}, **attrs),
             pixel=kw.get("pixel", pixel(n=1)), **{k: v for k, v in kw.items() if k != "pixel"})
        manifest.append((expect, [name + "_a.exr", name + "_b.exr"]))
    pair("their seed", "other_seed", {"pathlab.seed": b"8"})
    pair("their command", "other_command", {"pathlab.command": GOOD_ATTRS["pathlab.command"] + b" -H"})
    pair("their version", "other_version", {"pathlab.version": b"hostile-2"})
    pair("their render key", "other_key", {"pathlab.render_key": b"fedcba9876543210"})
    pair("their size", "other_size", {}, width=5)
    pair("their sample total", "other_total", {"pathlab.samples": b"1:2 of 3"})
    pair("n = 4 samples, expected 1", "range_holds_more", {}, pixel=pixel(n=4))
    pair("n = 4294967295 samples", "counts_wrap", {}, pixel=pixel(n=4294967295))
    with open(os.path.join(out, "manifest.txt"), "w") as f:
        for expect, files in manifest:
            f.write("%s|%s\n" % (expect, " ".join(files)))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_hostile_films.py DIR")
    main(sys.argv[1])
