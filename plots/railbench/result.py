"""In-memory, validated copy of the groups of a railbench result file (load_result)."""
from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .style import KINEMATIC_KINDS
from .h5 import ResultFileError, open_h5, _attrs, _read_ds, _str


@dataclass
class Schema:
    """The layout the file states in /schema (architecture.md, "Output layout"): per dataset its
    unit, meaning and the name of its codes; per code-valued quantity its code -> name table.
    Empty for files written before /schema existed."""
    units: Dict[str, str] = field(default_factory=dict)       # dataset path -> unit
    meaning: Dict[str, str] = field(default_factory=dict)     # dataset path -> what it is
    codes: Dict[str, str] = field(default_factory=dict)       # dataset path -> enum name
    enums: Dict[str, Dict[int, str]] = field(default_factory=dict)  # enum name -> {code: name}

    def names(self, enum: str) -> Dict[int, str]:
        return self.enums.get(enum, {})

    def children(self, group: str) -> List[str]:
        """Names of the datasets directly under `group`, in the order the schema lists them."""
        pre = group.rstrip("/") + "/"
        return [p[len(pre):] for p in self.units if p.startswith(pre) and "/" not in p[len(pre):]]


def parse_codes(text) -> Dict[int, str]:
    """"0=tangent,1=transition" -> {0: "tangent", 1: "transition"} (an enum attribute)."""
    out = {}
    for item in _str(text).split(","):
        code, sep, name = item.partition("=")
        if sep and code.strip().lstrip("-").isdigit():
            out[int(code)] = name.strip()
    return out


def _read_schema(f) -> Schema:
    import h5py
    sc = Schema()
    g = f.get("schema")
    if not isinstance(g, h5py.Group):
        return sc
    for part, t in g.items():
        if part == "enums" or not isinstance(t, h5py.Group) or "path" not in t:
            continue
        cols = {k: [_str(x) for x in t[k][()]] if k in t else [] for k in
                ("path", "unit", "meaning", "codes")}
        for i, p in enumerate(cols["path"]):
            sc.units[p] = cols["unit"][i] if i < len(cols["unit"]) else ""
            sc.meaning[p] = cols["meaning"][i] if i < len(cols["meaning"]) else ""
            if i < len(cols["codes"]) and cols["codes"][i]:
                sc.codes[p] = cols["codes"][i]
    if isinstance(g.get("enums"), h5py.Group):
        sc.enums = {k: parse_codes(v) for k, v in g["enums"].attrs.items()}
    return sc


@dataclass
class Track:
    attrs: Dict[str, object]
    centreline: Dict[str, np.ndarray]  # s x y z heading slope cant_angle curvature cant
    segments: Dict[str, np.ndarray]    # start length kind radius side cant
    kinds: Dict[int, str] = field(default_factory=dict)  # segment kind code -> name (the file's)
    sides: Dict[int, str] = field(default_factory=dict)  # segment side code -> name (the file's)

    def kind_name(self, code) -> str:
        k = int(round(code))
        return self.kinds.get(k, f"kind {k}")

    def side_name(self, code) -> str:
        k = int(round(code))
        return self.sides.get(k, "left" if k > 0 else "right")

    @property
    def n_segments(self) -> int:
        return int(self.segments["start"].size)

    def segment_bounds(self) -> np.ndarray:
        """Arc length of every segment boundary, start of the first to end of the last."""
        st, ln = self.segments["start"], self.segments["length"]
        if st.size == 0:
            s = self.centreline["s"]
            return np.array([s[0], s[-1]])
        return np.append(st, st[-1] + ln[-1])


@dataclass
class Irregularities:
    attrs: Dict[str, object]
    data: Dict[str, np.ndarray]                 # s, alignment, vertical, gauge, cross_level, ...
    target: Optional[Dict[str, np.ndarray]]     # omega + channels, or None (e.g. csv source)
    channels: Tuple[str, ...] = ()              # the irregularity channels, in the file's order

    @property
    def step(self) -> float:
        s = self.data["s"]
        return float(np.median(np.diff(s))) if s.size > 1 else float("nan")

    def band(self) -> Tuple[Optional[float], Optional[float]]:
        lo, hi = self.attrs.get("wavelength_min"), self.attrs.get("wavelength_max")
        lo = float(lo) if isinstance(lo, (int, float)) and lo > 0 else None
        hi = float(hi) if isinstance(hi, (int, float)) and hi > 0 else None
        return lo, hi

    def describe(self) -> str:
        a = self.attrs
        src = a.get("source", "?")
        if src == "psd":
            txt = f"spectrum {a.get('spectrum', '?')}, seed {a.get('seed', '?')}"
        else:
            txt = f"source {src}"
        lo, hi = self.band()
        if lo and hi:
            txt += f", λ = {lo:g}–{hi:g} m"
        sc = a.get("scale")
        if isinstance(sc, (int, float)) and sc != 1:
            txt += f", scale {sc:g}"
        return txt


@dataclass
class Body:
    name: str
    kind: str                        # "car", "bogie", "wheelset", "frame" (or as the file says)
    data: Dict[str, np.ndarray]      # s y z roll pitch yaw (+ rates etc.), SI units as stored

    def has(self, *keys: str) -> bool:
        return all(k in self.data and self.data[k].size > 0 for k in keys)

    @property
    def title(self) -> str:
        return body_title(self.name)


def body_title(name: str) -> str:
    """Display name: "ws1" -> "wheelset 1", "bogie2" -> "bogie 2", "car" -> "car body"."""
    import re
    m = re.fullmatch(r"(ws|wheelset|bogie|car|carbody|car_body)[ _]?(\d*)", name, re.IGNORECASE)
    if not m:
        return name
    word = {"ws": "wheelset", "carbody": "car body", "car_body": "car body",
            "car": "car body"}.get(m.group(1).lower(), m.group(1).lower())
    return f"{word} {m.group(2)}".strip()


@dataclass
class WheelsetContact:
    name: str                                              # wheelset (body) name
    sides: Dict[str, Dict[str, np.ndarray]]                # "left"/"right" -> datasets
    data: Dict[str, np.ndarray]                            # datasets of the wheelset itself

    def side(self, side: str, key: str) -> Optional[np.ndarray]:
        v = self.sides.get(side, {}).get(key)
        return v if v is not None and v.size > 0 else None


@dataclass
class Contact:
    attrs: Dict[str, object]
    wheelsets: Dict[str, WheelsetContact]                  # in vehicle order

    def has_any(self, keys: Sequence[str]) -> bool:
        for wc in self.wheelsets.values():
            for k in keys:
                if any(wc.side(sd, k) is not None for sd in ("left", "right")):
                    return True
                if k in wc.data and wc.data[k].size:
                    return True
        return False


@dataclass
class Result:
    path: str
    attrs: Dict[str, object]
    groups: List[str]                    # top-level group/dataset names present in the file
    track: Optional[Track] = None
    irregularities: Optional[Irregularities] = None
    extra: Dict[str, object] = field(default_factory=dict)  # room for later groups
    time: Optional[np.ndarray] = None                       # /time [s]
    bodies: Dict[str, Body] = field(default_factory=dict)   # /bodies, in vehicle order
    contact: Optional[Contact] = None                       # /contact
    elements: Dict[str, Dict[str, np.ndarray]] = field(default_factory=dict)  # /elements
    element_units: Dict[str, Dict[str, str]] = field(default_factory=dict)    # their units
    stats: Optional[Dict[str, object]] = None               # /stats attributes
    schema: Schema = field(default_factory=Schema)          # /schema (empty in older files)
    # A run of several vehicles (train{}): their names (/vehicles/<name>), and the one whose
    # groups this Result holds ("" for the file's root groups: the track and the run's /stats).
    vehicles: List[str] = field(default_factory=list)
    vehicle: str = ""

    @property
    def prefix(self) -> str:
        """Where this Result's vehicle groups are: "" or "/vehicles/<name>"."""
        return f"/vehicles/{self.vehicle}" if self.vehicle else ""

    @property
    def stem(self) -> str:
        return os.path.splitext(os.path.basename(self.path))[0]

    @property
    def failed(self) -> bool:
        return bool(self.stats) and str(self.stats.get("status", "ok")).strip().lower() == "failed"

    @property
    def contact_method(self) -> Optional[str]:
        """The wheel/rail contact method ("kec", "lut"); None without contact (track-only
        runs, and guided runs, whose file says "none (wheelsets guided)")."""
        # A vehicle of a run of several: its own /contact (the root attribute is the first's).
        m = None if self.vehicle else self.attrs.get("contact_method")
        if not m and self.contact is not None:
            m = self.contact.attrs.get("method")
        m = str(m).strip() if m else ""
        return m if m and not m.lower().startswith("none") else None

    @property
    def guided(self) -> bool:
        """A vehicle run whose wheelsets follow the track (no contact block)."""
        if self.vehicle:
            return self.contact is None and any(b.kind == "wheelset" for b in self.bodies.values())
        return str(self.attrs.get("contact_method", "")).strip().lower().startswith("none")

    def label(self) -> str:
        """Short run label for legends: contact method in capitals (KEC, LUT), else the stem."""
        m = self.contact_method
        return m.upper() if m else self.stem

    def kinematic_bodies(self, kinds: Sequence[str] = KINEMATIC_KINDS) -> List[str]:
        """Names of bodies of the given kinds that can be drawn against distance (have s)."""
        return [n for n, b in self.bodies.items() if b.kind in kinds and b.has("s")]

    def t_reached(self) -> Optional[float]:
        t = self.stats.get("t_reached") if self.stats else None
        if isinstance(t, (int, float)) and math.isfinite(t):
            return float(t)
        if self.time is not None and self.time.size:
            ok = self.time[np.isfinite(self.time)]
            return float(ok[-1]) if ok.size else None
        return None

    def read_group(self, group: str) -> Dict[str, np.ndarray]:
        """All 1-D datasets directly under `group` (lazy reader for figures added later)."""
        import h5py
        with open_h5(self.path, ResultFileError, "result file") as f:
            if group not in f:
                raise ResultFileError(f"missing group {group}")
            g = f[group]
            return {k: _read_ds(g, k, group) for k, v in g.items()
                    if isinstance(v, h5py.Dataset)}


# The datasets the figures need; their units are the file's /schema (unchecked without one).
_CENTRELINE = ("s", "x", "y", "z", "heading", "slope", "cant_angle", "curvature", "cant")
_SEGMENTS = ("start", "length", "kind", "radius", "side", "cant")
_IRR = ("s", "alignment", "vertical", "gauge", "cross_level")
_IRR_OPTIONAL = ("left_y", "left_z", "right_y", "right_z", "delta")


def _guess_kind(name: str) -> str:
    n = name.lower()
    if n.startswith(("ws", "wheelset")):
        return "wheelset"
    if n.startswith("bogie"):
        return "bogie"
    if n.startswith("car"):
        return "car"
    return "other"


def _names_attr(v) -> List[str]:
    """A newline-separated string (or an array of strings) -> list of names."""
    if isinstance(v, np.ndarray) and v.ndim == 1:
        items = [_str(x) for x in v]
    else:
        items = _str(v).splitlines()
    return [x.strip() for x in items if x.strip()]


def _read_series(group, where: str, schema: Schema,
                 finite: bool = False) -> Dict[str, np.ndarray]:
    """All 1-D numeric datasets directly under `group` (others are skipped silently), their
    units checked against the file's /schema; with `finite`, every sample finite."""
    import h5py
    out = {}
    for k, d in group.items():
        if not isinstance(d, h5py.Dataset) or d.dtype.kind not in "fiub" or d.ndim > 1:
            continue
        out[k] = _read_ds(group, k, where, schema.units.get(f"{where}/{k}"), finite=finite)
    return out


def _load_dynamics(root, res: Result) -> None:
    """Optional groups /time, /stats and the vehicle's /bodies, /contact, /elements (under
    res.prefix in a run of several vehicles) into `res`."""
    import h5py
    ragged: List[str] = []
    n_t = None
    if "stats" in root:
        res.stats = _attrs(root["stats"])
    # A run that finished ok never writes a NaN (check-result counts one as a problem): one in its
    # file is forged or damaged. A failed run's last outputs may be NaN where its evaluation
    # failed, and are drawn as the gap they are.
    finite = bool(res.stats) and res.stats.get("status") == "ok"
    if "time" in root and isinstance(root["time"], h5py.Dataset):
        res.time = _read_ds(root, "time", "", res.schema.units.get("/time"), finite=finite)
        n_t = res.time.size
    pre = res.prefix
    f = root[pre] if pre else root

    def note_len(where, arrays):
        if n_t is not None:
            ragged.extend(f"{where}/{k}" for k, v in arrays.items() if v.size != n_t)

    if "bodies" in f and isinstance(f["bodies"], h5py.Group):
        g = f["bodies"]
        present = [k for k, v in g.items() if isinstance(v, h5py.Group)]
        names = _names_attr(g.attrs["names"]) if "names" in g.attrs else []
        missing = [n for n in names if n not in present]
        if missing:
            print(f"railbench: warning: {res.path}: /bodies names {', '.join(missing)} "
                  f"without a group", file=sys.stderr)
        order = [n for n in names if n in present] + [n for n in present if n not in names]
        for n in order:
            bg = g[n]
            kind = _str(bg.attrs["kind"]).strip().lower() if "kind" in bg.attrs else _guess_kind(n)
            data = _read_series(bg, f"{pre}/bodies/{n}", res.schema, finite)
            note_len(f"{pre}/bodies/{n}", data)
            res.bodies[n] = Body(name=n, kind=kind, data=data)
        if res.bodies and not any("s" in b.data for b in res.bodies.values()):
            print(f"railbench: warning: {res.path}: no body has an 's' dataset (distance); "
                  f"body figures skipped", file=sys.stderr)

    if "contact" in f and isinstance(f["contact"], h5py.Group):
        g = f["contact"]
        wss = [k for k, v in g.items() if isinstance(v, h5py.Group)]
        body_order = [n for n in res.bodies if n in wss]
        wss = body_order + sorted(n for n in wss if n not in body_order)
        cws = {}
        for w in wss:
            wg = g[w]
            sides = {}
            for side in ("left", "right"):
                if side in wg and isinstance(wg[side], h5py.Group):
                    sides[side] = _read_series(wg[side], f"{pre}/contact/{w}/{side}",
                                               res.schema, finite)
                    note_len(f"{pre}/contact/{w}/{side}", sides[side])
            data = _read_series(wg, f"{pre}/contact/{w}", res.schema, finite)
            note_len(f"{pre}/contact/{w}", data)
            cws[w] = WheelsetContact(name=w, sides=sides, data=data)
        res.contact = Contact(attrs=_attrs(g), wheelsets=cws)

    if "elements" in f and isinstance(f["elements"], h5py.Group):
        for k, v in f["elements"].items():
            if isinstance(v, h5py.Group):
                res.elements[k] = _read_series(v, f"{pre}/elements/{k}", res.schema, finite)
                res.element_units[k] = {d: _str(v[d].attrs["units"]).strip()
                                        for d in res.elements[k] if "units" in v[d].attrs}
                note_len(f"{pre}/elements/{k}", res.elements[k])

    if ragged:
        print(f"railbench: warning: {res.path}: {len(ragged)} time series differ in length "
              f"from /time ({n_t} samples; interrupted run?), e.g. {ragged[0]}; plotted up to "
              f"their common length", file=sys.stderr)


def _stored_track_file(path: str, g) -> str:
    """The track store file a reference /track (attribute `stored_in`) names, relative to the
    result's folder (workbench run --track-store, workbench/io/track_store.hpp)."""
    rel = _str(g.attrs["stored_in"]).strip()
    if not rel:
        raise ResultFileError(f"{path}: /track has an empty 'stored_in'")
    return os.path.join(os.path.dirname(os.path.abspath(path)), rel)


def _open_stored_track(path: str, g):
    """The open track store file of a reference /track and its /track group, after checking that
    its track_hash equals the reference's. Raises ResultFileError naming both files."""
    store = _stored_track_file(path, g)
    want = _str(g.attrs.get("track_hash", "")).strip()
    if not want:
        raise ResultFileError(f"{path}: /track has 'stored_in' but no 'track_hash'")
    try:
        sf = open_h5(store, ResultFileError, "track store file")
    except ResultFileError as e:
        raise ResultFileError(f"{path}: its track store file (/track/stored_in): {e}") from None
    try:
        sg = sf["track"] if "track" in sf else None
        got = _str(sg.attrs.get("track_hash", "")).strip() if sg is not None else ""
    except (OSError, KeyError, ValueError) as e:
        sf.close()
        raise ResultFileError(f"{path}: cannot read its track store file {store} ({e})") from None
    if sg is None or got != want:
        sf.close()
        what = "has no /track group" if sg is None else f"holds track {got or '(no hash)'}"
        raise ResultFileError(f"{path}: its track store file {store} {what}, the result "
                              f"references track {want}")
    return sf, sg


def _read_track(path: str, g, res: Result) -> None:
    """/track (centreline, segments, irregularities) of group `g` into `res`."""
    for sub in ("centreline", "segments"):
        if sub not in g:
            raise ResultFileError(f"{path}: missing group /track/{sub}")
    units = res.schema.units
    cl = {k: _read_ds(g["centreline"], k, "/track/centreline", units.get(f"/track/centreline/{k}"))
          for k in _CENTRELINE}
    n = cl["s"].size
    if n < 2:
        raise ResultFileError(f"{path}: /track/centreline/s has {n} sample(s)")
    bad = [k for k, v in cl.items() if v.size != n]
    if bad:
        raise ResultFileError(f"{path}: /track/centreline datasets differ in length "
                              f"({', '.join(bad)} vs s={n})")
    sg = {k: _read_ds(g["segments"], k, "/track/segments", units.get(f"/track/segments/{k}"))
          for k in _SEGMENTS}
    m = sg["start"].size
    if any(v.size != m for v in sg.values()):
        raise ResultFileError(f"{path}: /track/segments datasets differ in length")
    # The codes of kind and side: /schema/enums, else the segments' own `codes` attribute.
    kinds = res.schema.names(res.schema.codes.get("/track/segments/kind", "segment_kind"))
    if not kinds and "codes" in g["segments"].attrs:
        kinds = parse_codes(g["segments"].attrs["codes"])
    sides = res.schema.names(res.schema.codes.get("/track/segments/side", "segment_side"))
    res.track = Track(attrs=_attrs(g), centreline=cl, segments=sg, kinds=kinds, sides=sides)

    if "irregularities" in g:
        ig = g["irregularities"]
        where = "/track/irregularities"
        data = {k: _read_ds(ig, k, where, units.get(f"{where}/{k}")) for k in _IRR}
        for k in _IRR_OPTIONAL:
            if k in ig:
                data[k] = _read_ds(ig, k, where, units.get(f"{where}/{k}"))
        named = res.schema.names("irregularity_channel")
        # The channels: /schema/enums, else (older files) the required datasets after s.
        channels = tuple(named[k] for k in sorted(named)) or _IRR[1:]
        ni = data["s"].size
        if any(data[k].size != ni for k in _IRR):
            raise ResultFileError(f"{path}: /track/irregularities datasets differ in length")
        target = None
        if "target_psd" in ig:
            tg, tw = ig["target_psd"], where + "/target_psd"
            target = {"omega": _read_ds(tg, "omega", tw, units.get(f"{tw}/omega"))}
            for c in channels:
                if c in tg:
                    target[c] = _read_ds(tg, c, tw, units.get(f"{tw}/{c}"))
        res.irregularities = Irregularities(attrs=_attrs(ig), data=data, target=target,
                                            channels=channels)


def load_result(path: str, vehicle: str = "") -> Result:
    """Open and validate a result file. Raises ResultFileError with a one-line message. A /track
    that references a track store file (attribute `stored_in`) is read from that file; the
    track's attributes are the store's with the result's own (build_time_s, stored_in,
    track_hash) on top. In a run of several vehicles (/vehicles), `vehicle` names the one whose
    groups are read ("": the root groups, which hold the track and /stats only)."""
    hint = " (a run still in progress writes '<name>.tmp')" if os.path.exists(path + ".tmp") else ""
    f = open_h5(path, ResultFileError, "result file", hint)
    try:
        with f:
            vehicles = []
            if "vehicles" in f:  # in the run's order, front to rear (attribute `names`)
                g = f["vehicles"]
                listed = _names_attr(g.attrs["names"]) if "names" in g.attrs else []
                vehicles = [n for n in listed if n in g] + sorted(n for n in g if n not in listed)
            if vehicle and vehicle not in vehicles:
                raise ResultFileError(f"{path}: no vehicle '{vehicle}' (vehicles: "
                                      f"{', '.join(vehicles) or 'none'})")
            base = f[f"vehicles/{vehicle}"] if vehicle else f
            res = Result(path=path, attrs=_attrs(f), groups=sorted(base.keys()),
                         schema=_read_schema(f), vehicles=vehicles, vehicle=vehicle)
            if "track" not in f:
                raise ResultFileError(f"{path}: no /track group (not a railbench result file?)")
            g = f["track"]
            if "stored_in" in g.attrs:
                sf, sg = _open_stored_track(path, g)
                with sf:
                    _read_track(path, sg, res)
                res.track.attrs.update(_attrs(g))
            else:
                _read_track(path, g, res)
            _load_dynamics(f, res)
            return res
    except ResultFileError:
        raise
    except (OSError, KeyError, ValueError) as e:
        raise ResultFileError(f"{path}: cannot read ({str(e).splitlines()[0] if str(e) else e!r})") \
            from None


# --------------------------------------------------------------------------------------------
