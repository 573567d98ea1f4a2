#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL MLS_projection authors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
"""The projection benchmark on simulated scans of CAD parts: mls_project against PCL's
MovingLeastSquares, whole processes, in the same run. Run through scripts/benchmark, which
builds the programs; see benchmark/MLS_projection/README.md for what is measured and why.

Each part (an OpenSCAD example exported as a mesh) is sampled with `scan_part` at every seed and
noise level (points without normals). On each scan run, one after the other, several times:
  PCL       pcl_mls, polynomial order 2, radius 4 average spacings, one thread
  P_L       mls_project --operator levin --space quadratic --threads 1
  default   mls_project with its defaults, --threads 1, and again with --threads 2
  isolated  mls_project --no-warm-starts --threads 1 (the defaults otherwise) on a subset of the
            points as --queries: each query alone, the mesher's and the library's case; its cost
            per query is the time of that run minus that of the same run with one query (the
            reading, the search structure and the noise estimate), over the number of queries
The times are medians of the runs (wall clock of the whole process: reading, the search
structure, projecting, writing); the errors are the distances of the output points to the
part's mesh as fractions of its bounding-box diagonal (RMS and maximum).
With --meshing, mls_mesh and CGAL's Poisson mesh the same scans (or, with --defects, scans with
the defects of real scans: sparse, outliers, a hole, open), measured by `scan_part mesh`.
"""

import argparse
import filecmp
import math
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time

EXAMPLES = "/usr/share/openscad/examples/Old/"
PARTS = {  # name: (OpenSCAD file or source, definitions)
    "example002": (EXAMPLES + "example002.scad", ["-D", "$fn=96"]),
    "example006": (EXAMPLES + "example006.scad", []),
    "example009": (EXAMPLES + "example009.scad", []),  # a fan: thin blades
    # smooth, no crease: the hull of an ellipsoid and a sphere
    "blob": ("hull() { scale([1, 0.7, 0.5]) sphere(r=10, $fn=120); translate([9, 0, 3]) sphere(r=4, $fn=90); }", []),
}
# The defects of real scans (--defects), per part: a point of a crease, the centre of the hole, and
# the cut of the open scan (the points with coordinate `axis` below `below` are kept).
DEFECTS = {
    "example002": {"crease_point": (9.5, 0., 15.), "axis": 2, "below": -2.},  # the top rim; the lower half
}


def run(cmd, quiet=True):
    """Runs `cmd`; returns (seconds, peak resident KiB). Raises on failure."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE if quiet else None, stderr=subprocess.PIPE)
    _, _, rusage = os.wait4(proc.pid, 0)
    seconds = time.perf_counter() - start
    out, err = proc.communicate()
    if proc.returncode != 0:
        raise RuntimeError("%s failed:\n%s" % (" ".join(cmd), err.decode(errors="replace")))
    return seconds, rusage.ru_maxrss


def run_until(cmd, timeout):
    """Runs `cmd` for at most `timeout` seconds; returns (seconds, peak resident KiB, exit status
    or None when killed at the timeout, the last line of stderr)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    status = None
    while True:
        pid, wstatus, rusage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            status = os.waitstatus_to_exitcode(wstatus)
            break
        if time.perf_counter() - start > timeout:
            proc.kill()
            _, _, rusage = os.wait4(proc.pid, 0)
            break
        time.sleep(0.05)
    seconds = time.perf_counter() - start
    err = proc.stderr.read().decode(errors="replace").strip().splitlines()
    return seconds, rusage.ru_maxrss, status, err[-1] if err else ""


def output_of(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def median_time(cmd, runs):
    times, memory = [], 0
    for _ in range(runs):
        t, m = run(cmd)
        times.append(t)
        memory = max(memory, m)
    return statistics.median(times), memory


def distances(tools, mesh, points):
    fields = output_of([tools["scan_part"], "distance", mesh, points]).split()
    values = dict(zip(fields[0::2], fields[1::2]))
    return float(values["rms"]), float(values["max"])


def export_part(name, work):
    scad, definitions = PARTS[name]
    mesh = os.path.join(work, name + ".off")
    if not scad.endswith(".scad"):
        source, scad = scad, os.path.join(work, name + ".scad")
        with open(scad, "w") as f:
            f.write(source + "\n")
    if not os.path.exists(mesh):
        subprocess.run(["openscad", *definitions, "-o", mesh, scad], check=True, capture_output=True)
    return mesh


def subset(points, out, stride):
    with open(points) as src, open(out, "w") as dst:
        for i, line in enumerate(src):
            if i % stride == 0:
                dst.write(line)


def measure_scan(tools, mesh, scan, n, args, log):
    spacing = float(output_of([tools["scan_part"], "spacing", scan]).split()[-1])
    radius = 4 * spacing
    d = os.path.dirname(scan)
    row = {}
    cases = {
        "PCL": [tools["pcl_mls"], scan, os.path.join(d, "pcl.xyz"), repr(radius), "1"],
        "P_L": [tools["mls_project"], "--input", scan, "--output", os.path.join(d, "levin.xyz"),
                "--operator", "levin", "--space", "quadratic", "--threads", "1", "--quiet"],
        "default": [tools["mls_project"], "--input", scan, "--output", os.path.join(d, "default.xyz"),
                    "--threads", "1", "--quiet"],
        "default2": [tools["mls_project"], "--input", scan, "--output", os.path.join(d, "default2.xyz"),
                     "--threads", "2", "--quiet"],
    }
    stride = max(1, n // args.isolated)
    queries = os.path.join(d, "queries.xyz")
    subset(scan, queries, stride)
    one_query = os.path.join(d, "one_query.xyz")
    subset(scan, one_query, n)
    cases["isolated"] = [tools["mls_project"], "--input", scan, "--queries", queries, "--output",
                         os.path.join(d, "isolated.xyz"), "--no-warm-starts", "--threads", "1", "--quiet"]
    cases["setup"] = cases["isolated"][:4] + [one_query] + cases["isolated"][5:]
    for name, cmd in cases.items():
        row[name], row[name + "_memory"] = median_time(cmd, args.runs)
        log("    %-9s %.3f s" % (name, row[name]))
    row["queries"] = (n + stride - 1) // stride
    row["per_query"] = max(0., row["isolated"] - row["setup"]) / row["queries"]
    for name, out in (("PCL", "pcl.xyz"), ("P_L", "levin.xyz"), ("default", "default.xyz")):
        row[name + "_rms"], row[name + "_max"] = distances(tools, mesh, os.path.join(d, out))
    return row


def scaled_scan(tools, mesh, work, part, noise, args, log):
    """A scan of --scale points of `mesh` (seed 1), with the noise level `noise` of --points scaled
    by sqrt(points / scale): the same noise in spacings, so that the two sizes are the same regime
    and their times compare. Returns the scan's path and its noise level."""
    scaled = float(noise) * math.sqrt(args.points / args.scale)
    d = os.path.join(work, "%s_scale_n%s" % (part, noise))
    os.makedirs(d, exist_ok=True)
    scan = os.path.join(d, "scan.xyz")
    subprocess.run([tools["scan_part"], "sample", mesh, str(args.scale), repr(scaled), "1", scan], check=True)
    log("%s, %d points, noise %g" % (part, args.scale, scaled))
    return scan, scaled


def measure_meshing(tools, mesh, scan, args, log, mls_options=(), scan_distances=False):
    """mls_mesh with its defaults (and `mls_options`) and poisson_mesh on `scan`, both on all cores;
    their time, peak memory and `scan_part mesh` figures against the part `mesh` (and, with
    `scan_distances`, the vertices' distances to the part and the scan's to the mesh). mls_mesh
    again with one thread: its speed-up on all cores and whether the two meshes are the same, byte
    for byte."""
    d = os.path.dirname(scan)
    rows = []
    cases = {
        "MLS": [tools["mls_mesh"], "--input", scan, "--output", os.path.join(d, "mls.off"), "--quiet", *mls_options],
        "Poisson": [tools["poisson_mesh"], scan, os.path.join(d, "poisson.off")],
    }
    for name, cmd in cases.items():
        out = cmd[-1] if name == "Poisson" else cmd[4]
        if os.path.exists(out):
            os.remove(out)
        seconds, memory, status, message = run_until(cmd, args.timeout)
        row = {"method": name, "seconds": seconds, "memory": memory, "message": message}
        if status is None:
            row["message"] = "no mesh: stopped after %.0f s" % args.timeout
        elif status < 0:
            row["message"] = "no mesh: crashed (signal %d)" % -status
        elif status != 0:
            row["message"] = "no mesh: " + re.sub(r"^.*failed: ", "", message)
        fields = output_of([tools["scan_part"], "mesh", mesh, out]).split() if os.path.exists(out) else ["none"]
        row.update(dict(zip(fields[0::2], fields[1::2])))
        if scan_distances and os.path.exists(out):
            row["vertex_rms"], row["vertex_max"] = distances(tools, mesh, out)
            row["scan_rms"], _ = distances(tools, out, scan)
        log("    %-8s %.1f s %s" % (name, seconds, " ".join(fields)))
        if name == "MLS" and status == 0:
            single = os.path.join(d, "mls_1_thread.off")
            cmd1 = cmd[:4] + [single] + cmd[5:] + ["--threads", "1"]
            seconds1, _, status1, _ = run_until(cmd1, args.timeout)
            if status1 == 0:
                row["speedup"] = seconds1 / seconds
                row["same_mesh"] = filecmp.cmp(out, single, shallow=False)
                log("    1 thread %.1f s, %s mesh" % (seconds1, "the same" if row["same_mesh"] else "another"))
        rows.append(row)
    return rows


def read_xyz(path):
    with open(path) as f:
        return [tuple(float(v) for v in line.split()[:3]) for line in f if line.strip()]


def write_xyz(path, points):
    with open(path, "w") as f:
        f.writelines("%.9g %.9g %.9g\n" % p for p in points)


def defect_scans(tools, mesh, part, work, args):
    """The scans with the defects of real scans, of `part` (noiseless, seed 1): (name, scan,
    mls_mesh options). Sparse: 1000 and 3000 points. Outliers: `--defect-points` points and 5 %
    more uniform in the bounding box enlarged by 10 %. Hole: `--defect-points` points without those
    within 3 % of the diagonal of a point of a crease. Open: twice as many points, of which those
    on one side of a plane (a scan from one side), meshed with `mls_mesh --open`."""
    def sample(n, name):
        d = os.path.join(work, "%s_%s" % (part, name))
        os.makedirs(d, exist_ok=True)
        scan = os.path.join(d, "scan.xyz")
        subprocess.run([tools["scan_part"], "sample", mesh, str(n), "0", "1", scan], check=True)
        return scan
    scans = []
    for n in (1000, 3000):
        scans.append(("sparse, %d points" % n, sample(n, "sparse%d" % n), []))
    scan = sample(args.defect_points, "outliers")
    points = read_xyz(scan)
    lo = [min(p[a] for p in points) for a in range(3)]
    hi = [max(p[a] for p in points) for a in range(3)]
    rng = random.Random(1)
    points += [tuple(lo[a] - 0.05 * (hi[a] - lo[a]) + 1.1 * (hi[a] - lo[a]) * rng.random() for a in range(3))
               for _ in range(len(points) // 20)]
    write_xyz(scan, points)
    scans.append(("5 % outliers", scan, []))
    defect = DEFECTS[part]
    scan = sample(args.defect_points, "hole")
    points = read_xyz(scan)
    radius = 0.03 * math.dist(lo, hi)
    write_xyz(scan, [p for p in points if math.dist(p, defect["crease_point"]) > radius])
    scans.append(("hole across a crease", scan, []))
    scan = sample(2 * args.defect_points, "open")
    write_xyz(scan, [p for p in read_xyz(scan) if p[defect["axis"]] < defect["below"]])
    scans.append(("open scan", scan, ["--open"]))
    return scans


def print_defects(rows):
    print("## Meshing scans with defects (mls_mesh defaults, --open for the open scan, against CGAL's Poisson, "
          "both on all cores, one run)\n")
    print("| part | case | points | method | s | peak MB | closed | manifold | components | Hausdorff | RMS | "
          "normal error (deg) | sharp-edge distance | vertices to part: RMS | max | scan to mesh: RMS | note |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        get = lambda k: r.get(k, "-")
        note = r["message"] if r["message"].startswith("no mesh") else ""
        number = lambda k: "%.3g" % r[k] if k in r else "-"
        print("| %s | %s | %d | %s | %.1f | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["part"], r["case"], r["points"], r["method"], r["seconds"], r["memory"] / 1024., get("closed"),
            get("manifold"), get("components"), get("hausdorff"), get("rms"), get("normal_deg"), get("edge_distance"),
            number("vertex_rms"), number("vertex_max"), number("scan_rms"), note))
    mls = [r for r in rows if r["method"] == "MLS"]
    print("\nMLS: a mesh for %d of %d scans (closed and manifold: %d)" % (
        sum(1 for r in mls if "closed" in r), len(mls),
        sum(1 for r in mls if r.get("closed") == "1" and r.get("manifold") == "1")))


def print_meshing(rows, points):
    print("## Meshing scans of CAD parts (%d points, mls_mesh defaults against CGAL's Poisson, both on all "
          "cores, one run)\n" % points)
    print("| part | noise | seed | method | s | peak MB | closed | manifold | components | self-intersecting | "
          "Hausdorff | RMS | normal error (deg) | sharp-edge distance | 1 thread / all | note |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        get = lambda k: r.get(k, "-")
        note = r["message"] if r["message"].startswith("no mesh") else ""
        features = re.search(r"(\d+) feature polylines, (\d+) corners( \(not protected)?", r["message"])
        if r["method"] == "MLS" and features and not note:
            dropped = re.search(r"(\d+) polylines off the surface dropped", r["message"])
            note = "%s polylines, %s corners%s%s" % (features.group(1), features.group(2),
                                                    ", not protected" if features.group(3) else "",
                                                    " (%s off the surface dropped)" % dropped.group(1) if dropped else "")
        threads = "-"
        if "speedup" in r:
            threads = "%.2f%s" % (r["speedup"], "" if r["same_mesh"] else ", another mesh")
        print("| %s | %g | %s | %s | %.1f | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["part"], r["noise"], r["seed"], r["method"], r["seconds"], r["memory"] / 1024., get("closed"),
            get("manifold"), get("components"), get("self_intersecting"), get("hausdorff"), get("rms"),
            get("normal_deg"), get("edge_distance"), threads, note))
    mls = [r for r in rows if r["method"] == "MLS"]
    good = sum(1 for r in mls if r.get("closed") == "1" and r.get("manifold") == "1")
    pairs = list(zip(rows[0::2], rows[1::2]))
    print("\nMLS: %d closed manifold meshes of %d scans; MLS / Poisson, medians: time %.2f, peak memory %.2f" % (
        good, len(mls), statistics.median(m["seconds"] / p["seconds"] for m, p in pairs),
        statistics.median(m["memory"] / p["memory"] for m, p in pairs)))
    timed = [r for r in mls if "speedup" in r]
    if timed:
        print("MLS, one thread against all cores: median speed-up %.2f (lowest %.2f); the same mesh on %d of %d scans"
              % (statistics.median(r["speedup"] for r in timed), min(r["speedup"] for r in timed),
                 sum(1 for r in timed if r["same_mesh"]), len(timed)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", required=True, help="the directory of mls_project, scan_part and pcl_mls")
    parser.add_argument("--parts", default="example002,example006")
    parser.add_argument("--points", type=int, default=50000)
    parser.add_argument("--noise", default="0,0.002", help="noise levels, fractions of the diagonal")
    parser.add_argument("--seeds", default="1,2")
    parser.add_argument("--runs", type=int, default=3, help="runs per measurement (the median is kept)")
    parser.add_argument("--isolated", type=int, default=2000, help="queries of the isolated case")
    parser.add_argument("--scale", type=int, default=0,
                        help="also project (or, with --meshing, mesh) this many points of the first part (e.g. 1000000)")
    parser.add_argument("--work", default=None, help="directory of the scans (default: a temporary one)")
    parser.add_argument("--meshing", action="store_true", help="mesh the scans (mls_mesh, poisson_mesh) instead")
    parser.add_argument("--timeout", type=float, default=900, help="seconds after which a mesher is stopped")
    parser.add_argument("--defects", action="store_true",
                        help="with --meshing: mesh scans with defects (sparse, outliers, a hole, open) of the first "
                             "part instead")
    parser.add_argument("--defect-points", type=int, default=10000, help="points of the outliers and hole scans")
    args = parser.parse_args()

    names = ("mls_mesh", "scan_part", "poisson_mesh") if args.meshing else ("mls_project", "scan_part", "pcl_mls")
    tools = {t: os.path.join(args.bin, t) for t in names}
    for t, path in tools.items():
        if not os.access(path, os.X_OK):
            sys.exit("scan_benchmark: %s not found in %s" % (t, args.bin))
    work = args.work or tempfile.mkdtemp(prefix="mls_scans_")
    os.makedirs(work, exist_ok=True)
    log = lambda s: print(s, file=sys.stderr, flush=True)

    if args.defects:
        part = args.parts.split(",")[0]
        if part not in DEFECTS:
            sys.exit("scan_benchmark: no defects defined for %s (DEFECTS)" % part)
        mesh = export_part(part, work)
        rows = []
        for case, scan, options in defect_scans(tools, mesh, part, work, args):
            log("%s, %s" % (part, case))
            for row in measure_meshing(tools, mesh, scan, args, log, options, scan_distances=True):
                row.update(part=part, case=case, points=len(read_xyz(scan)))
                rows.append(row)
        print_defects(rows)
        return

    rows = []
    for part in args.parts.split(","):
        mesh = export_part(part, work)
        for noise in args.noise.split(","):
            for seed in args.seeds.split(","):
                d = os.path.join(work, "%s_n%s_s%s" % (part, noise, seed))
                os.makedirs(d, exist_ok=True)
                scan = os.path.join(d, "scan.xyz")
                subprocess.run([tools["scan_part"], "sample", mesh, str(args.points), noise, seed, scan], check=True)
                log("%s, noise %s, seed %s" % (part, noise, seed))
                if args.meshing:
                    for row in measure_meshing(tools, mesh, scan, args, log):
                        row.update(part=part, noise=float(noise), seed=seed)
                        rows.append(row)
                    continue
                row = measure_scan(tools, mesh, scan, args.points, args, log)
                row.update(part=part, noise=float(noise), seed=seed)
                rows.append(row)
    if args.meshing:
        print_meshing(rows, args.points)
        if args.scale:
            part = args.parts.split(",")[0]
            mesh = export_part(part, work)
            rows = []
            for noise in args.noise.split(","):
                scan, _ = scaled_scan(tools, mesh, work, part, noise, args, log)
                for row in measure_meshing(tools, mesh, scan, args, log):
                    row.update(part=part, noise=float(noise), seed="1")
                    rows.append(row)
            print()
            print_meshing(rows, args.scale)
            print("\n(noise: at %d points; the scan's is scaled by sqrt(%d / %d), the same in spacings)"
                  % (args.points, args.points, args.scale))
        return

    print("## Projection on scans of CAD parts (%d points, medians of %d runs, one thread unless said)\n"
          % (args.points, args.runs))
    print("| part | noise | seed | PCL s | P_L / PCL | default / PCL | 2 threads speed-up | isolated default "
          "per query / PCL's per point | RMS PCL | RMS P_L | RMS default | max PCL | max P_L | max default |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        per_query = r["per_query"] / (r["PCL"] / args.points)
        print("| %s | %g | %s | %.2f | %.2f | %.2f | %.2f | %.1f | %.2e | %.2e | %.2e | %.2e | %.2e | %.2e |" % (
            r["part"], r["noise"], r["seed"], r["PCL"], r["P_L"] / r["PCL"], r["default"] / r["PCL"],
            r["default"] / r["default2"], per_query, r["PCL_rms"], r["P_L_rms"], r["default_rms"], r["PCL_max"],
            r["P_L_max"], r["default_max"]))
    ratio = lambda key: statistics.median(r[key] / r["PCL"] for r in rows)
    print("\nMedians over the scans: P_L / PCL %.2f, default / PCL %.2f, 2 threads speed-up %.2f, "
          "isolated default per query / PCL's per point %.1f" % (
              ratio("P_L"), ratio("default"), statistics.median(r["default"] / r["default2"] for r in rows),
              statistics.median(r["per_query"] / (r["PCL"] / args.points) for r in rows)))

    if args.scale:
        part = args.parts.split(",")[0]
        mesh = export_part(part, work)
        print("\n## Scale: %d points of %s, one thread, one run\n" % (args.scale, part))
        print("| noise at %d points | noise at %d points | PCL s | default s | default / PCL | "
              "default at %d / at %d points (linear: %.1f) | PCL bytes per point | default bytes per point | "
              "RMS PCL | RMS default | max PCL | max default |"
              % (args.points, args.scale, args.scale, args.points, args.scale / args.points))
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for noise in args.noise.split(","):
            scan, scaled = scaled_scan(tools, mesh, work, part, noise, args, log)
            d = os.path.dirname(scan)
            spacing = float(output_of([tools["scan_part"], "spacing", scan]).split()[-1])
            pcl, pcl_memory = run([tools["pcl_mls"], scan, os.path.join(d, "pcl.xyz"), repr(4 * spacing), "1"])
            ours, memory = run([tools["mls_project"], "--input", scan, "--output", os.path.join(d, "default.xyz"),
                                "--threads", "1", "--quiet"])
            small = statistics.median(r["default"] for r in rows if r["part"] == part and r["noise"] == float(noise))
            pcl_rms, pcl_max = distances(tools, mesh, os.path.join(d, "pcl.xyz"))
            rms, worst = distances(tools, mesh, os.path.join(d, "default.xyz"))
            print("| %s | %.2g | %.1f | %.1f | %.2f | %.1f | %.0f | %.0f | %.2e | %.2e | %.2e | %.2e |" % (
                noise, scaled, pcl, ours, ours / pcl, ours / small,
                pcl_memory * 1024. / args.scale, memory * 1024. / args.scale, pcl_rms, rms, pcl_max, worst))

if __name__ == "__main__":
    main()
