#!/usr/bin/env python3
"""Writes the seeds of the result harness (tests/fuzz/result/*.bin) in its grammar
(result_files.cpp, README.md): each seed is a list of operations. The vocabularies are read from
result_files.cpp, so an index here is the name there. Run from anywhere:
    /usr/bin/python3 tests/fuzz/make_result_seeds.py"""
import os
import re
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = open(os.path.join(HERE, "result_files.cpp")).read()


def vocab(name):
    body = re.search(name + r" = \{(.*?)\};", SRC, re.S).group(1)
    return [bytes(s, "ascii").decode("unicode_escape") for s in re.findall(r'"((?:[^"\\]|\\.)*)"', body)]


PARTS, ATTRS, TEXTS, FILES = (vocab(n) for n in ("kParts", "kAttrNames", "kTexts", "kLinkFiles"))


def path(p):
    if p == "/":
        return bytes([16])
    rel = not p.startswith("/")
    parts = p.strip("/").split("/")
    out = bytes([(len(parts) - 1) | (8 if rel else 0)])
    for c in parts:
        out += bytes([PARTS.index(c)]) if c in PARTS else bytes([255, len(c)]) + c.encode()
    return out


def base(n_code=200, coarse=False, flags=0):
    return bytes([0, n_code, 1 if coarse else 0, flags])


def select(file_id):
    return bytes([1, file_id])


def group(p):
    return bytes([2]) + path(p)


def dataset(p, kind=0, shape=0, layout=0, n=10, gen=1, scale=12, salt=0, special=0, at=0,
            decades=0):
    t = kind | (shape << 3) | (layout << 5)
    out = bytes([3]) + path(p) + bytes([t]) + struct.pack("<H", n)
    if layout == 4:
        return out + bytes([decades])
    if layout in (5, 6):
        return out
    return out + bytes([gen, scale, salt, special]) + struct.pack("<H", at)


def attr(obj, name, shape=0, value=0, count=0):
    """shape 0 f64, 1 i64, 2 fixed string, 3 vlen string, 4 f64 array, 5 null, 6 f32, 7 vlen
    array; value: an index of kNumbers / kTexts, or a float / str (raw)."""
    n = bytes([255, len(name)]) + name.encode() if name not in ATTRS else bytes([ATTRS.index(name)])
    if isinstance(value, float):
        v = bytes([255]) + struct.pack("<d", value)
    elif isinstance(value, str):
        v = bytes([TEXTS.index(value)]) if value in TEXTS else bytes([255, len(value)]) + value.encode()
    else:
        v = bytes([value])
    return bytes([4]) + path(obj) + n + bytes([shape]) + v + bytes([count])


def soft(link, target):
    return bytes([5]) + path(link) + path(target)


def external(link, file, obj):
    f = bytes([FILES.index(file)]) if file in FILES else bytes([255, len(file)]) + file.encode()
    return bytes([6]) + path(link) + f + path(obj)


def hard(link, existing):
    return bytes([7]) + path(link) + path(existing)


def delete(p):
    return bytes([8]) + path(p)


def assessment(n=801, flags=0):
    return bytes([9]) + struct.pack("<H", n) + bytes([flags])



SEEDS = {
    # flags byte first: bit 0 exit code 2, bits 1-2 t_end (0, 2, 1, 10 s), bit 3 no assess.
    "plain": bytes([0]) + base(),
    "plain_ws": bytes([2]) + base(flags=32),
    "assessment": bytes([0]) + base() + assessment(),
    "assessment_all": bytes([0]) + base(flags=2) + assessment(flags=2 | 4 | 16 | 32),
    "assessment_short": bytes([0]) + base() + assessment(n=3),
    "assessment_one": bytes([0]) + base(n_code=0, flags=2) + assessment(n=1, flags=2 | 4 | 16 | 32),
    "assessment_two": bytes([0]) + base(n_code=0, flags=2) + assessment(n=2, flags=2 | 4 | 16 | 32),
    "assessment_half_second": bytes([0]) + base(n_code=50, flags=2) +
    assessment(n=200, flags=2 | 4 | 8 | 16 | 32),
    "outputs_two": bytes([0]) + base(n_code=0, flags=2) + dataset("/time", n=2, gen=1, scale=9),
    "assessment_tangent": bytes([0]) + base() + assessment(flags=4 | 8),
    "nan_assessment": bytes([0]) + base() + assessment() +
    delete("/assessment/safety/ws1/left/Y") +
    dataset("/assessment/safety/ws1/left/Y", n=801, gen=2, scale=15, special=1, at=400),
    "nan_signal": bytes([0]) + base(flags=32) + delete("/bodies/ws/y") +
    dataset("/bodies/ws/y", n=801, gen=2, scale=9, special=1, at=100),
    "inf_attribute": bytes([0]) + base() + assessment() + attr("/assessment", "mu", 0, 16),
    "external_schema": bytes([0]) + base() + external("/schema", "../victim.h5", "/schema"),
    "external_self": bytes([0]) + base() + external("/contact/ws1/left/Q", "fuzz.h5", "/time"),
    "soft_loop": bytes([0]) + base() + soft("/metrics", "/metrics") + soft("/vehicles", "/time"),
    "hard_cycle": bytes([0]) + base() + hard("/contact/ws1/left/up", "/contact"),
    "fifo_store": bytes([0]) + base() + attr("/track", "stored_in", 2, "fifo.h5") +
    attr("/track", "track_hash", 2, "0123456789abcdef"),
    "stored_track": bytes([0]) + base(flags=16),
    "stored_track_outside": bytes([0]) + base(flags=16) +
    attr("/track", "stored_in", 2, "../victim.h5"),
    "huge_declared": bytes([0]) + base() + delete("/contact/ws1/left/Q") +
    dataset("/contact/ws1/left/Q", layout=4, decades=11),
    "fill_nan": bytes([0]) + base() + delete("/time") + dataset("/time", n=801, layout=5),
    "deflate": bytes([0]) + base() + delete("/bodies/ws1/y") +
    dataset("/bodies/ws1/y", n=801, layout=7, gen=4, scale=9),
    "types": bytes([0]) + base() + dataset("/stats/stage_names", kind=4, n=5) +
    dataset("/stats/stage_share", kind=1, n=5, gen=3, scale=11) +
    dataset("/bodies/ws1/z", kind=7, n=20) + dataset("/bodies/ws1/yaw", kind=2, shape=3, n=40) +
    dataset("/vehicle/speed", kind=0, shape=1) + dataset("/track/segments/start", shape=2),
    "two_vehicles_failed": bytes([1 | 2]) + base(flags=1 | 4),
    "irregular_track": bytes([4]) + base(flags=8),
    "reference": bytes([8]) + base(flags=32) + select(1) + base(n_code=100, flags=32) +
    select(0) + attr("/bodies/ws", "kind", 2, "wheelset"),
    "metrics_group": bytes([8]) + base(flags=32) + attr("/metrics", "names", 2, "y_max\ny_win\nq_time\ny_ss\nyq\nyq_path\ny_err\nq_fn") +
    attr("/metrics", "y_max", 0, 15) + attr("/metrics", "yq", 0, 1) +
    attr("/assessment/summary", "y_over_q", 0, 16) + attr("/", "input_hash", 2, "0123456789abcdef"),
    "stored_metrics": bytes([8]) + base(flags=32) +
    attr("/metrics", "names", 2, "y_max\ny_win\nq_time\ny_ss\nyq\nyq_path\ny_err\nq_fn") +
    attr("/metrics", "definitions_hash", 2, "<metrics hash>") + attr("/metrics", "y_max", 0, 16) +
    attr("/metrics", "yq", 0, 1) + attr("/metrics", "y_err", 0, 15) + attr("/metrics", "q_fn", 0, 2) +
    attr("/metrics", "y_win", 0, 1) + attr("/metrics", "q_time", 0, 1) +
    attr("/metrics", "y_ss", 0, 1) + attr("/metrics", "yq_path", 0, 1),
    "array_attribute": bytes([1]) + base() + attr("/stats", "t_reached", 4, 3, 255),
    "coarse_outputs": bytes([0]) + base(coarse=True, flags=2),
}

if __name__ == "__main__":
    out = os.path.join(HERE, "result")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name + ".bin"), "wb") as f:
            f.write(data)
    print(f"{len(SEEDS)} seeds in {out}")
