#!/usr/bin/python3
"""Reference data for the switch-and-crossing (S&C) CONTACT comparison (tests/data/contact_sc/).

Reads the CONTACT test bank (eve70a/CONTACT, Apache-2.0) from a bare git mirror and writes, next to
this script:
  - the rail profiles of the three S&C slice files as plain `y z` text (mm, z UP, y as in the .prr,
    i.e. the left-rail profile parameter of railbench, +y = field side), cut at slope 1:1;
  - slices.csv: per original slice, which file and which (dy, dz) translation of it reproduces it;
  - contact_sc_reference.csv: CONTACT's reference results (.ref_out) per case and patch.
It prints the geometry check (translation fits and residuals) to stdout.

Our own code; only numbers are taken from the CONTACT files. Needs python3 + numpy.
Usage: /usr/bin/python3 extract.py [path/to/CONTACT/bare/repo [uk_crossing]]
With `uk_crossing` it instead copies the S&C benchmark's UK crossing (uk_crossing.slcs and its
slice files, unmodified) and writes uk_crossing_reference.csv from CONTACT's mbench_brute case.
"""
import os
import re
import subprocess
import sys

import numpy as np

REPO = sys.argv[1] if len(sys.argv) > 1 else '/work/.mirror/eve70a+CONTACT/repo'
OUT = os.path.dirname(os.path.abspath(__file__))
PROFILES = os.path.join(OUT, '..', '..', '..', 'profiles')  # the UK crossing's rails, for scenarios
MAX_SLOPE = 1.0  # parts are cut where |dz/dy| first exceeds this on the way down the flanks


def git(*args):
    return subprocess.run(['git', '-C', REPO] + list(args), capture_output=True, text=True,
                          check=True).stdout


COMMIT = git('rev-parse', 'HEAD').strip()


def show(path):
    return git('show', COMMIT + ':' + path)


# ---------------------------------------------------------------------------------------------
# SIMPACK .prr reading (as railbench's reader does it: units.len.f, mirror.y, mirror.z honoured;
# rail z is DOWN in the file, returned UP)

def read_prr(path):
    keys, pts, inpts = {}, [], False
    for ln in show(path).splitlines():
        s = ln.split('!')[0].strip()
        if not s:
            continue
        if s == 'point.begin':
            inpts = True
            continue
        if s == 'point.end':
            inpts = False
            continue
        if inpts:
            pts.append([float(v) for v in s.replace(',', ' ').split()[:2]])
        elif '=' in s:
            k, v = s.split('=', 1)
            keys[k.strip()] = v.strip().strip("'")
        elif s.endswith('.begin') or s.endswith('.end'):
            keys.setdefault('_blocks', []).append(s)
    for k in ('shift.y', 'shift.z', 'rotate'):
        if float(keys.get(k, '0')) != 0.0:
            raise ValueError(f'{path}: {k} not supported')
    a = np.array(pts)
    f = float(keys.get('units.len.f', '1'))  # l[user] / l[m]
    y = a[:, 0] * (1000.0 / f)
    z = a[:, 1] * (1000.0 / f)
    if float(keys.get('mirror.y', '0')) != 0.0:
        y = -y
    if float(keys.get('mirror.z', '0')) != 0.0:
        z = -z
    if keys.get('type', '0').strip() != '0':
        raise ValueError(f'{path}: not a rail profile')
    o = np.argsort(y)
    return keys, y[o], -z[o]  # z up


def read_slcs(path):
    lines = [ln.split('%')[0].strip() for ln in show(path).splitlines()]
    lines = [ln for ln in lines if ln]
    nslc = int(lines[1].split()[0])
    nfeat = int(lines[2].split()[0])
    nkink, naccel = int(lines[2].split()[1]), int(lines[2].split()[2])
    assert nkink == 0 and naccel == 0
    i = 4
    slices = []
    for k in range(nslc):
        u, name = lines[i + k].split(None, 1)
        slices.append((float(u), name.strip().strip("'")))
    i += nslc
    feats = np.array([[float(v) for v in lines[i + k].split()] for k in range(nslc)])
    assert feats.shape == (nslc, nfeat + 1) and np.allclose(feats[:, 0], [s[0] for s in slices])
    return slices, feats[:, 1:]


def arclen(y, z):
    return np.r_[0.0, np.cumsum(np.hypot(np.diff(y), np.diff(z)))]


# ---------------------------------------------------------------------------------------------
# geometry helpers

def polyline_distance(P, Q):
    """Signed normal distance of points P (n,2) to the polyline Q (m,2) and the unit normal of the
    nearest segment (normal = tangent rotated +90 degrees: points 'up' for a y-ascending polyline)."""
    A, B = Q[:-1], Q[1:]
    d = B - A
    L2 = (d ** 2).sum(1)
    t = ((P[:, None, :] - A[None]) * d[None]).sum(2) / L2[None]
    t = np.clip(t, 0.0, 1.0)
    C = A[None] + t[..., None] * d[None]
    D = P[:, None, :] - C
    dist = np.hypot(D[..., 0], D[..., 1])
    j = dist.argmin(1)
    nrm = np.stack([-d[:, 1], d[:, 0]], 1) / np.sqrt(L2)[:, None]
    n = nrm[j]
    r = (D[np.arange(len(P)), j] * n).sum(1)
    return r, n


def fit_translation(base, pts, guess):
    """(dy, dz) with pts - (dy, dz) on the base polyline, least squares in the normal distance,
    using the points whose shifted y lies inside the base's y range."""
    s = np.array(guess, float)
    for _ in range(30):
        P = pts - s
        m = (P[:, 0] >= base[0, 0]) & (P[:, 0] <= base[-1, 0])
        r, n = polyline_distance(P[m], base)
        J = -n  # d r / d s
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        s += step
        if np.abs(step).max() < 1e-12:
            break
    P = pts - s
    m = (P[:, 0] >= base[0, 0]) & (P[:, 0] <= base[-1, 0])
    r, _ = polyline_distance(P[m], base)
    return s, r, m


def head_run(y, z, max_slope=MAX_SLOPE, anchor=None):
    """Index range [i0, i1] (inclusive) of the longest-around-the-anchor run of consecutive points whose
    chord slopes satisfy |dz/dy| <= max_slope; the anchor defaults to the highest point."""
    sl = np.abs(np.diff(z) / np.diff(y))
    k = int(np.argmax(z)) if anchor is None else anchor
    i0 = k
    while i0 > 0 and sl[i0 - 1] <= max_slope:
        i0 -= 1
    i1 = k
    while i1 < len(y) - 1 and sl[i1] <= max_slope:
        i1 += 1
    return i0, i1


def fmt(x):
    s = '%.6f' % x
    return '0.000000' if s == '-0.000000' else s


def write_profile(name, y, z, header):
    with open(os.path.join(OUT, name), 'w') as f:
        for h in header:
            f.write('# ' + h + '\n' if h else '#\n')
        f.write('# y_mm z_mm\n')
        for a, b in zip(y, z):
            f.write(f'{fmt(a)} {fmt(b)}\n')


def common_header(src, how):
    return [
        f'Source: CONTACT (E.A.H. Vollebregt, Vtech CMCC; github.com/eve70a/CONTACT), commit {COMMIT},',
        f'  {src}',
        '  Licence: Apache License 2.0 (https://www.apache.org/licenses/LICENSE-2.0; text in',
        '  profiles/LICENSE-Apache-2.0.txt). Distributed "AS IS", without warranties of any kind.',
        'Convention: y [mm] as in the .prr (no mirror keys there) = railbench left-rail profile parameter,',
        '  +y toward the FIELD side (CONTACT canonical right-rail profile); z [mm] UP (= minus the .prr z).',
    ] + how + ['Derived by tests/data/contact_sc/extract.py; see README.md in this folder.']


# ---------------------------------------------------------------------------------------------
# part 1/2: geometry

def load_case(slcs):
    slices, feats = read_slcs('testbank/profiles/' + slcs)
    data = []
    for (u, name), F in zip(slices, feats):
        keys, y, z = read_prr('testbank/profiles/' + name)
        data.append(dict(u=u, file='testbank/profiles/' + name, keys=keys, y=y, z=z, feat=F))
    return data


def point_at_s(d, s):
    sa = arclen(d['y'], d['z'])
    return np.array([np.interp(s, sa, d['y']), np.interp(s, sa, d['z'])])


def part_points(d, s0, s1):
    sa = arclen(d['y'], d['z'])
    m = (sa >= s0 - 1e-9) & (sa <= s1 + 1e-9)
    return d['y'][m], d['z'][m]


def translation_study(label, data, ubase, part, guess_feat):
    """part(d) -> (y, z) of the part in slice d; returns rows with u, dy, dz, residuals."""
    b = next(d for d in data if d['u'] == ubase)
    by, bz = part(b)
    base = np.c_[by, bz]
    h0, h1 = head_run(by, bz)
    rows = []
    print(f'\n== {label}: base slice u = {ubase:g} ({b["file"]}), {len(by)} part points, '
          f'head (|slope| <= {MAX_SLOPE:g}) y = {by[h0]:.3f} .. {by[h1]:.3f}')
    print('     u       dy        dz     rms_all   max_all  n_used  max_head')
    for d in data:
        y, z = part(d)
        pts = np.c_[y, z]
        g = point_at_s(d, d['feat'][guess_feat]) - point_at_s(b, b['feat'][guess_feat])
        s, r, m = fit_translation(base, pts, g)
        # residual on the head part only: slice points whose shifted y lies in the base head range
        P = pts - s
        mh = (P[:, 0] >= by[h0]) & (P[:, 0] <= by[h1])
        rh, _ = polyline_distance(P[mh], base)
        rows.append(dict(u=d['u'], dy=s[0], dz=s[1], rms=np.sqrt(np.mean(r ** 2)),
                         max=np.abs(r).max(), n=int(m.sum()), maxh=np.abs(rh).max(),
                         nout=int((~m).sum())))
        print('  %6.1f %9.5f %9.5f  %8.1e  %8.1e  %4d/%-4d %8.1e' % (
            d['u'], s[0], s[1], rows[-1]['rms'], rows[-1]['max'], m.sum(), len(y), rows[-1]['maxh']))
    return rows, (by, bz, h0, h1)


def main():
    print('CONTACT commit', COMMIT)
    csv_slices = []
    summary = {}

    # ---- header keys of all .prr files used
    for slcs in ('cross_nose.slcs', 'wing_rail.slcs', 'cross+wing.slcs'):
        data = load_case(slcs)
        keysets = {tuple(sorted(k for k in d['keys'] if k not in ('comment', '_blocks'))) for d in data}
        vals = {tuple(sorted((k, v) for k, v in d['keys'].items() if k not in ('comment', '_blocks')))
                for d in data}
        print(f'{slcs}: {len(data)} slices; .prr keys {keysets}; distinct key values {len(vals)}: {vals}')

    # ---- cross_nose: whole profile, base u = 0 (wheel at S = 0)
    data = load_case('cross_nose.slcs')
    rows, (by, bz, h0, h1) = translation_study('cross_nose (nose)', data, 0.0,
                                               lambda d: (d['y'], d['z']), 2)
    for r in rows:
        print('    u=%6.1f  dz - u/10 = %.2e   dy = %.2e   top z = %.4f' % (
            r['u'], r['dz'] - r['u'] / 10, r['dy'],
            next(d for d in data if d['u'] == r['u'])['z'].max()))
    summary['cross_nose'] = rows
    write_profile('nose.txt', by[h0:h1 + 1], bz[h0:h1 + 1], common_header(
        f'testbank/profiles/cross_nose/nose_11.prr (slice u = 0 of testbank/profiles/cross_nose.slcs)',
        ['Artificial crossing nose "rising at 1:10": every slice of cross_nose.slcs is this profile',
         '  translated by (dy, dz) = (0, u/10) mm (slices.csv). Kept: the head between the points where',
         f'  |dz/dy| first exceeds {MAX_SLOPE:g} on both flanks (y = {by[h0]:.3f} .. {by[h1]:.3f} mm);',
         '  cut: the 80-degree flanks (slope 5.67) and the floor at z = -37.8 mm on the field side.']))
    for r in rows:
        csv_slices.append(('cross_nose', 'nose', r['u'], 'nose.txt', r['dy'], r['dz']))

    # ---- wing_rail: whole profile, base u = 100 (wheel at S = 100)
    data = load_case('wing_rail.slcs')
    rows, (by, bz, h0, h1) = translation_study('wing_rail (wing)', data, 100.0,
                                               lambda d: (d['y'], d['z']), 2)
    for r in rows:
        print('    u=%6.1f  dy - (u-100)/10 = %.2e   dz = %.2e' % (
            r['u'], r['dy'] - (r['u'] - 100) / 10, r['dz']))
    summary['wing_rail'] = rows
    write_profile('wing.txt', by[h0:h1 + 1], bz[h0:h1 + 1], common_header(
        f'testbank/profiles/wing_rail/wing_11.prr (slice u = 100 of testbank/profiles/wing_rail.slcs)',
        ['Artificial wing rail "shifting sideways at 1:10": every slice of wing_rail.slcs is this',
         '  profile translated by (dy, dz) = ((u - 100)/10, 0) mm (slices.csv), +dy = field side.',
         f'  Kept: the head between the points where |dz/dy| first exceeds {MAX_SLOPE:g} on both flanks',
         f'  (y = {by[h0]:.3f} .. {by[h1]:.3f} mm); cut: the flanks (slope 5.67) and the floor at',
         '  z = -41.9 mm on the gauge side.']))
    for r in rows:
        csv_slices.append(('wing_rail', 'wing', r['u'], 'wing.txt', r['dy'], r['dz']))

    # ---- cross+wing: nose = features 1..6, floor 6..7, wing = features 7..10
    data = load_case('cross+wing.slcs')
    nose = lambda d: part_points(d, d['feat'][0], d['feat'][5])
    wing = lambda d: part_points(d, d['feat'][6], d['feat'][9])
    for d in data:
        (ny, nz), (wy, wz) = nose(d), wing(d)
        fl_y, fl_z = part_points(d, d['feat'][5], d['feat'][6])
        print('  cw u=%5.1f nose y %.3f..%.3f top %.4f | floor y %.3f..%.3f z %.3f..%.3f | '
              'wing y %.3f..%.3f top %.4f' % (d['u'], ny[0], ny[-1], nz.max(), fl_y[0], fl_y[-1],
                                              fl_z.min(), fl_z.max(), wy[0], wy[-1], wz.max()))
    rows_w, (by, bz, h0, h1) = translation_study('cross+wing wing part', data, 100.0, wing, 7)
    for r in rows_w:
        print('    u=%6.1f  dy - (u-100)/10 = %.2e   dz = %.2e' % (
            r['u'], r['dy'] - (r['u'] - 100) / 10, r['dz']))
    summary['cw_wing'] = rows_w
    write_profile('cw_wing.txt', by[h0:h1 + 1], bz[h0:h1 + 1], common_header(
        'testbank/profiles/cross+wing/cross+wing_16.prr (slice u = 100 of testbank/profiles/cross+wing.slcs)',
        ['Wing-rail part of the combined crossing nose + wing rail profile (the points from S_F',
         '  feature 7 to 10, arc length from the profile start). Every slice\'s wing part is this',
         '  profile translated by (dy, dz) = ((u - 100)/10, 0) mm (slices.csv), +dy = field side.',
         f'  Kept: from where |dz/dy| first exceeds {MAX_SLOPE:g} on its gauge-side flank (y = {by[h0]:.3f}',
         f'  mm) to the end of the profile (y = {by[h1]:.3f} mm; flat top, no field-side flank in the',
         '  file). Cut: the near-vertical gauge face (slope up to 19) and the floor between wing and nose.']))
    for r in rows_w:
        csv_slices.append(('cross+wing', 'wing', r['u'], 'cw_wing.txt', r['dy'], r['dz']))

    # nose part: try a translation of the u = 100 nose; then the two halves separately
    rows_n, _ = translation_study('cross+wing nose part, as one translation (expected to fail)', data,
                                  100.0, nose, 2)
    half_g = lambda d: part_points(d, d['feat'][0], 0.5 * (d['feat'][2] + d['feat'][3]))
    half_f = lambda d: part_points(d, 0.5 * (d['feat'][2] + d['feat'][3]), d['feat'][5])
    rows_g, _ = translation_study('cross+wing nose, gauge half (start .. middle of flat top)', data,
                                  100.0, half_g, 1)
    rows_f, _ = translation_study('cross+wing nose, field half (middle of flat top .. floor)', data,
                                  100.0, half_f, 4)
    for r in rows_f:
        print('    u=%6.1f  field half dy - (u-100)/10 = %.2e   dz = %.2e' % (
            r['u'], r['dy'] - (r['u'] - 100) / 10, r['dz']))
    summary['cw_nose'] = (rows_n, rows_g, rows_f)
    for d in data:
        ny, nz = nose(d)
        i0, i1 = head_run(ny, nz)
        name = 'cw_nose_u%03d.txt' % round(d['u'])
        write_profile(name, ny[i0:i1 + 1], nz[i0:i1 + 1], common_header(
            f'{d["file"]} (slice u = {d["u"]:g} of testbank/profiles/cross+wing.slcs)',
            ['Crossing-nose part of the combined nose + wing rail profile (the points from S_F feature',
             '  1 to 6). NOT a translation from slice to slice: the nose WIDENS at 1:10 (its gauge-side',
             '  half is the same in every slice, its field-side half moves by u/10 toward the field',
             '  side, the flat top at z = -2.25 mm grows in between), so each slice has its own file.',
             f'  Kept: between the points where |dz/dy| first exceeds {MAX_SLOPE:g} on both flanks',
             f'  (y = {ny[i0]:.3f} .. {ny[i1]:.3f} mm); cut: the flanks (slope 4) and the floors.']))
        csv_slices.append(('cross+wing', 'nose', d['u'], name, 0.0, 0.0))

    with open(os.path.join(OUT, 'slices.csv'), 'w') as f:
        f.write('# Rail slices of the CONTACT S&C test cases (eve70a/CONTACT commit %s, Apache-2.0):\n' % COMMIT)
        f.write('# slice u_mm of testbank/profiles/<case>.slcs = profile <file> translated by (dy_mm, dz_mm).\n')
        f.write('# dy > 0 toward the FIELD side (+y of the profile parameter), dz > 0 UP. Fitted by extract.py.\n')
        f.write('case,part,u_mm,file,dy_mm,dz_mm\n')
        for c, p, u, fn, dy, dz in csv_slices:
            f.write('%s,%s,%g,%s,%s,%s\n' % (c, p, u, fn, '%.6f' % round(dy, 6) if abs(dy) > 5e-7 else '0',
                                              '%.6f' % round(dz, 6) if abs(dz) > 5e-7 else '0'))

    extract_reference()


# ---------------------------------------------------------------------------------------------
# part 3: .ref_out numbers

NUM = re.compile(r'^[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$')


def isnum(t):
    return bool(NUM.match(t))


def table_pairs(lines):
    """(header tokens, value tokens) for every line of labels followed by a line of as many numbers."""
    out = []
    for a, b in zip(lines, lines[1:]):
        ha, vb = a.split(), b.split()
        if ha and len(ha) == len(vb) and all(isnum(v) for v in vb) and not any(isnum(h) for h in ha):
            out.append((ha, vb))
    return out


def table_values(lines):
    """Every label of the label/number line pairs in lines with its first value."""
    d = {}
    for h, v in table_pairs(lines):
        for a, b in zip(h, v):
            d.setdefault(a, b)
    return d


def ref_out_cases(txt):
    """(case number, its text, its header values, [(patch number, patch text, patch values)]) for
    every case of a .ref_out."""
    blocks = re.split(r'^ Case +(\d+)\s*$', txt, flags=re.M)
    for icase, body in zip(blocks[1::2], blocks[2::2]):
        g = table_values(body.split('----- DATA FOR CONTACT PATCH')[0].splitlines())
        parts = re.split(r'^ ----- DATA FOR CONTACT PATCH +(\d+) -----\s*$', body, flags=re.M)
        yield icase, body, g, [(ip, pb, table_values(pb.splitlines()))
                               for ip, pb in zip(parts[1::2], parts[2::2])]


def grid_extent(lines):
    """Rows (s) and columns (x) of the printed contact grid containing contact cells, and the cell count."""
    i = next(k for k, ln in enumerate(lines) if 'FORM OF THE CONTACT' in ln)
    rows = []
    for ln in lines[i + 1:]:
        m = re.match(r'^\s*(\d+)  (.*)$', ln)
        if not m:
            if rows:
                break
            continue
        body = m.group(2)
        cells = body[1::2] if body.startswith(' ') else body  # narrow grids are printed with spaces
        rows.append((int(m.group(1)), cells))
    contact = set('*S|')
    rs = [iy for iy, c in rows if any(ch in contact for ch in c)]
    ncol = max(len(c) for _, c in rows)
    cs = [j for j in range(ncol) if any(j < len(c) and c[j] in contact for _, c in rows)]
    ncells = sum(ch in contact for _, c in rows for ch in c)
    return len(rs), len(cs), ncells, (min(rs), max(rs))


def parse_control(inp):
    lines = [ln for ln in inp.splitlines() if ln.strip() and not ln.lstrip().startswith('%')]
    words = {}
    for ln in lines:
        t = ln.split()
        if len(t) >= 2 and re.fullmatch(r'\d{6,7}', t[0]) and re.fullmatch(r'[A-Z](-[A-Z])+', t[1]):
            words[t[1]] = t[0].rjust(len(t[1].split('-')), '0')
    return words


def extract_reference():
    cases = ['cross_brute', 'cross_locus', 'wing_brute', 'wing_locus', 'cross+wing']
    cols = ['case', 'icase', 'slcs', 'discns', 'method', 's_ws_mm', 'y_ws_mm', 'z_ws_mm', 'roll_ws_rad',
            'yaw_ws_rad', 'fx_tr_N', 'fy_tr_N', 'fz_tr_N', 'npatch', 'patch', 'xcp_tr_mm', 'ycp_tr_mm',
            'zcp_tr_mm', 'deltcp_tr_rad', 'ycp_r_mm', 'zcp_r_mm', 'xcp_w_mm', 'ycp_w_mm', 'zcp_w_mm',
            'fn_N', 'fx_N', 'fs_N', 'mn_Nmm', 'cksi', 'ceta', 'cphi_per_mm', 'approach_mm', 'pmax_MPa',
            'npot', 'ncon', 'nadh', 'nslip', 'dx_mm', 'ds_mm', 'ncol_x', 'nrow_s', 'len_x_mm', 'len_s_mm']
    out = []
    for c in cases:
        inp = show(f'testbank/examples_s+c/{c}.inp')
        ctl = parse_control(inp)
        d_digit = int(ctl['V-L-D-C-M-Z-E'][2])
        method = {2: 'locus', 5: 'brute'}.get(d_digit, '?')
        slcs = re.search(r"'([^']+\.slcs)'", inp).group(1).split('/')[-1]
        txt = show(f'testbank/examples_s+c/{c}.ref_out')
        for icase, body, g, patches in ref_out_cases(txt):
            # TOTAL FORCES ON RAIL: FX(TR) ... FZ(WS)
            assert d_digit == int(re.search(r'DISCNS +(\d)', body).group(1))
            npatch = len(patches)
            for ip, pb, p in patches:
                nrow, ncol, ncells, _ = grid_extent(pb.splitlines())
                assert ncells == int(p['NCON']), (c, ncells, p['NCON'])
                dx, ds = float(g['DX']), float(g['DS'])
                out.append([c, icase, slcs, str(d_digit), method, g['S_WS'], g['Y_WS'], g['Z_WS'],
                            g['ROLL_WS'], g['YAW_WS'], g['FX(TR)'], g['FY(TR)'], g['FZ(TR)'], str(npatch),
                            ip, p['XCP(TR)'], p['YCP(TR)'], p['ZCP(TR)'], p['DELTCP(TR)'], p['YCP(R)'],
                            p['ZCP(R)'], p['XCP(W)'], p['YCP(W)'], p['ZCP(W)'], p['FN'], p['FX'], p['FS'],
                            p['MN'], p['CKSI'], p['CETA'], p['CPHI'], p['APPROACH'], p['PMAX'],
                            p['NPOT'], p['NCON'], p['NADH'], p['NSLIP'], g['DX'], g['DS'], str(ncol),
                            str(nrow), '%.2f' % (ncol * dx), '%.2f' % (nrow * ds)])
    with open(os.path.join(OUT, 'contact_sc_reference.csv'), 'w') as f:
        f.write('# CONTACT S&C test cases: reference results (eve70a/CONTACT testbank/examples_s+c/*.ref_out,\n')
        f.write(f'# commit {COMMIT}, Apache-2.0). Numbers as printed by CONTACT (one row per case and patch).\n')
        f.write('# CONTACT conventions: right wheel, track y to the RIGHT (= field side), z DOWN, mm, rad, N, MPa;\n')
        f.write('# len_x_mm / len_s_mm = rows/columns of the printed contact grid with contact cells times DX / DS.\n')
        f.write(','.join(cols) + '\n')
        for r in out:
            f.write(','.join(r) + '\n')
    for r in out:
        print(dict(zip(cols, r)))


# ---------------------------------------------------------------------------------------------
# part 4: the S&C benchmark's UK crossing (56E1, 1:9.25) and CONTACT's wheel over it (mbench_brute)

UK_COLS = ['icase', 's_ws_mm', 'y_ws_mm', 'z_ws_mm', 'fx_tr_N', 'fy_tr_N', 'fz_tr_N', 'npatch', 'patch',
           'xcp_tr_mm', 'deltcp_tr_rad', 'ycp_r_mm', 'zcp_r_mm', 'fn_N', 'fx_N', 'fs_N', 'approach_mm',
           'pmax_MPa', 'ncon']


def copy_uk_crossing():
    """uk_crossing.slcs and the 148 slice files it lists, unmodified, to profiles/ (and uk_crossing/)."""
    slcs = show('testbank/profiles/uk_crossing.slcs')
    os.makedirs(os.path.join(PROFILES, 'uk_crossing'), exist_ok=True)
    with open(os.path.join(PROFILES, 'uk_crossing.slcs'), 'w') as f:
        f.write(slcs)
    names = re.findall(r"'(uk_crossing/[^']+)'", slcs)
    for n in names:
        with open(os.path.join(PROFILES, n), 'w') as f:
            f.write(show('testbank/profiles/' + n))
    print(f'uk_crossing.slcs: {len(names)} slice files copied')
    # The rail opposite the crossing and its check rail: CONTACT has their slices and positions
    # (SectionPosition*.txt) but no slices-file; ours lists them in the same form.
    for part, slcs_name, title in (
            ('OppositeStockRail', 'uk_opposite_stock_rail.slcs', 'stock rail opposite the crossing'),
            ('CheckRail_Thr', 'uk_check_rail.slcs', 'check rail beside that stock rail')):
        pos_file = f'uk_crossing/SectionPosition{part}.txt'
        pos = show('testbank/profiles/' + pos_file)
        with open(os.path.join(PROFILES, pos_file), 'w') as f:
            f.write(pos)
        rows = [ln.split() for ln in pos.splitlines() if ln.strip()]
        with open(os.path.join(PROFILES, slcs_name), 'w') as f:
            f.write(f"% railbench's slices-file for the {title} of the S&C benchmark's UK crossing:\n")
            f.write(f"% the slices and positions of CONTACT's testbank/profiles/{pos_file}\n")
            f.write(f"% (eve70a/CONTACT commit {COMMIT}, Apache-2.0), written by extract.py.\n\n")
            f.write('   0.000    1000.0   U_OFFSET [usr], S_SCALE [mm/usr],  usr = m\n')
            f.write(f'   {len(rows):3d}             NSLC\n')
            f.write('     0    0    0   NFEAT, NKINK, NACCEL\n')
            f.write('     1             U_INTPOL (1=intpol, 2=approx)\n\n')
            for k, u in rows:
                name = f'uk_crossing/{part}_{k}.txt'
                with open(os.path.join(PROFILES, name), 'w') as g:
                    g.write(show('testbank/profiles/' + name))
                f.write(f" {float(u):10.5f}   '{name}'\n")
        print(f'{slcs_name}: {len(rows)} slices')
    # The stock rail as profiles.rail (the positioning's and the centred start's rail) reads it:
    # plain text in mm, z up (OppositeStockRail_1.txt converted; all six slices are the same).
    src = 'uk_crossing/OppositeStockRail_1.txt'
    with open(os.path.join(PROFILES, 'uk_crossing', 'stock_rail_56e1_mm.txt'), 'w') as f:
        f.write(f"# The 56E1 stock rail of the S&C benchmark's UK crossing: CONTACT's testbank/profiles/{src}\n")
        f.write(f'# (eve70a/CONTACT commit {COMMIT}, Apache-2.0) converted by extract.py to y z in mm, z UP.\n')
        for ln in show('testbank/profiles/' + src).splitlines():
            if ln.strip():
                y, z = (float(v) for v in ln.split()[:2])
                f.write(f'{y * 1000:.6f} {-z * 1000:.6f}\n')


def extract_uk_crossing():
    """One row per case and patch of mbench_brute.ref_out (the case's prescribed FZ in the .inp)."""
    txt = show('testbank/examples_s+c/mbench_brute.ref_out')
    out = []
    for icase, _, g, patches in ref_out_cases(txt):
        npatch = len(patches)
        for ip, _, p in patches:
            out.append([icase, g['S_WS'], g['Y_WS'], g['Z_WS'], g['FX(TR)'], g['FY(TR)'], g['FZ(TR)'],
                        str(npatch), ip, p['XCP(TR)'], p['DELTCP(TR)'], p['YCP(R)'], p['ZCP(R)'], p['FN'],
                        p['FX'], p['FS'], p['APPROACH'], p['PMAX'], p['NCON']])
    with open(os.path.join(OUT, 'uk_crossing_reference.csv'), 'w') as f:
        f.write('# CONTACT on the S&C benchmark UK crossing (56E1-R245-1:9.25): eve70a/CONTACT\n')
        f.write(f'# testbank/examples_s+c/mbench_brute.ref_out, commit {COMMIT}, Apache-2.0. Right wheel\n')
        f.write('# (MBench_S1002_v3.prw, FBDIST 1360, FBPOS -70, r0 460 mm) at S_WS = 239 mm over\n')
        f.write('# uk_crossing.slcs (RAILY0 750 mm, no cant), FZ = 10 kN prescribed, Y_WS swept; brute-force\n')
        f.write('# planar contact, grid 0.2 x 0.2 mm, f = 0.3, VS 2000 mm/s, VPITCH -4.3481181 rad/s.\n')
        f.write('# One row per case and patch; CONTACT conventions: y to the RIGHT (field side), z DOWN, mm.\n')
        f.write(','.join(UK_COLS) + '\n')
        for r in out:
            f.write(','.join(r) + '\n')
    print(f'uk_crossing_reference.csv: {len(out)} rows')


if __name__ == '__main__':
    if len(sys.argv) > 2 and sys.argv[2] == 'uk_crossing':
        copy_uk_crossing()
        extract_uk_crossing()
    else:
        main()
