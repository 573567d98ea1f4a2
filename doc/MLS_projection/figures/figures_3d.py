#!/usr/bin/env python3
"""The manual's 3D figures: the paper's Figure 7 and the case studies against CGAL's Poisson.

    figures_3d.py BENCH_MESHING RENDER_MESH WORK_DIR FIG_DIR

Runs the meshing benchmark (benchmark/MLS_projection/bench_meshing.cpp, which samples the analytic
solids, meshes them with this package and with CGAL's Poisson reconstruction in the same run and
measures both against the exact surface) once per case with --mesh-dir, renders the meshes with
scripts/render_mesh (sharp edges of the meshes in red, border edges in blue), composes the PNGs of
FIG_DIR and prints the figures quoted in the manual. Run by scripts/figures; deterministic (fixed
seeds, two threads: the meshes do not depend on the number of threads).
MLS_FIGURES_REUSE=1: redraw from the meshes and tables of the previous run in WORK_DIR."""

import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

BENCH, RENDER, WORK, FIG = sys.argv[1:5]
POINTS = 3000
# the built-in solid at 3000 points: spacing sqrt(10.63 / 3000) = 0.0595
SPACING = 0.0595

# name, title, shape, bench_meshing options, render views (elevation, azimuth)
FIGURE7 = [
    ("solid", "CSG solid (box, bore, fillet)", "solid", ["--space", "wedge", "--points", "12000"],
     [(25, -60), (-30, 120)]),
    ("fandisk", "fandisk-like block", "fandisk", ["--space", "wedge", "--points", "12000"], [(30, -70), (25, 120)]),
]
CASES = [
    ("ideal", "ideal sampling (3000 points, no noise)", "solid", [], (25, -60)),
    ("noise1", "noise sigma = 0.1 spacing", "solid+noise", ["--noise", "%.4g" % (0.1 * SPACING)], (25, -60)),
    ("noise2", "noise sigma = 0.25 spacing", "solid+noise", ["--noise", "%.4g" % (0.25 * SPACING)], (25, -60)),
    ("noise3", "noise sigma = 0.5 spacing", "solid+noise", ["--noise", "%.4g" % (0.5 * SPACING)], (25, -60)),
    ("sparse", "sparse sampling (1000 points)", "solid", ["--points", "1000"], (25, -60)),
    ("hole", "a hole (no samples within 0.2 of a point of the top front edge)", "solid",
     ["--hole", "0.3,-0.6,0.4,0.2"], (25, -60)),
    ("outliers", "5% outliers (uniform in the box, random normals)", "solid", ["--outliers", "0.05"], (25, -60)),
    ("creases", "sharp creases: the fandisk-like block", "fandisk", [], (30, -70)),
]
COLUMNS = ["shape", "points", "method", "seconds", "cpu s", "vertices", "facets", "closed", "vertex max",
           "vertex RMS", "Hausdorff", "RMS", "normal error (deg)", "edge distance", "features"]


def run_bench(name, shape, options, methods):
    out_dir = os.path.join(WORK, name)
    os.makedirs(out_dir, exist_ok=True)
    args = [BENCH, "--points", str(POINTS), "--threads", "2", "--shapes", shape, "--methods", methods,
            "--poisson-criteria", "default", "--mesh-dir", out_dir, "--max-meshing-seconds", "300"] + options
    print("figures_3d:", " ".join(args[1:]), flush=True)
    saved = os.path.join(out_dir, "bench.txt")
    if os.environ.get("MLS_FIGURES_REUSE") and os.path.exists(saved):
        with open(saved) as f:  # the meshes and figures of the previous run (to redraw only)
            stdout = f.read()
    else:
        res = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=True)
        stdout = res.stdout
        with open(saved, "w") as f:
            f.write(stdout)
        with open(os.path.join(out_dir, "bench.err"), "w") as f:
            f.write(res.stderr)
    rows = {}
    for line in stdout.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == len(COLUMNS) and cells[0] == shape:
            row = dict(zip(COLUMNS, cells))
            rows["mls" if row["method"].startswith("MLS") else "poisson"] = row
    return out_dir, rows


def render(mesh, png, view, size=1000):
    subprocess.run([RENDER, mesh, png, "--view", "%g,%g" % view, "--size", str(size), "--sharp", "30"], check=True)


def crop(image):
    """The image without its white margins."""
    ink = np.where(image[:, :, :3].min(axis=2) < 0.98)
    if len(ink[0]) == 0:
        return image
    (r0, r1), (c0, c1) = (ink[0].min(), ink[0].max()), (ink[1].min(), ink[1].max())
    return image[max(r0 - 10, 0):r1 + 10, max(c0 - 10, 0):c1 + 10]


def panel(images, titles, out, suptitle, columns):
    rows = (len(images) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(6.5 * columns, 4.8 * rows), squeeze=False, constrained_layout=True)
    for ax in axes.flat:
        ax.axis("off")
    for ax, image, title in zip(axes.flat, images, titles):
        ax.imshow(crop(plt.imread(image)))
        ax.set_title(title, fontsize=10)
    fig.suptitle(suptitle, fontsize=12)
    path = os.path.join(FIG, out)
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)
    print("wrote", path, flush=True)


def describe(row):
    if row is None:
        return "failed"
    if row["vertices"] == "failed":
        return "failed"
    return ("%s vertices, vertex max %s, Hausdorff %s, RMS %s, normal error %s deg, edge distance %s"
            % (row["vertices"], row["vertex max"], row["Hausdorff"], row["RMS"], row["normal error (deg)"],
               row["edge distance"]))


def figure7():
    images, titles = [], []
    for name, title, shape, options, views in FIGURE7:
        out_dir, rows = run_bench("fig7-" + name, shape, options, "mls")
        mesh = os.path.join(out_dir, shape + "-mls.off")
        for i, view in enumerate(views):
            png = os.path.join(out_dir, "view%d.png" % i)
            render(mesh, png, view)
            images.append(png)
            titles.append("%s, view %d" % (title, i + 1))
        row = rows.get("mls")
        print("figure7 %s: %s; %s; %s s" % (name, describe(row), row["features"] if row else "",
                                            row["seconds"] if row else ""))
    panel(images, titles, "meshes_wedge.png",
          "The wedge space, 12000 points, unified operator, Mesh_3 with the detected creases protected\n"
          "red: the mesh's edges sharper than 30 degrees", 2)


def case_studies():
    table = []
    for name, title, shape, options, view in CASES:
        out_dir, rows = run_bench("case-" + name, shape, options, "mls,poisson")
        images, titles = [], []
        for method, label in (("mls", "MLS (unified, mixed space)"), ("poisson", "Poisson (CGAL's defaults)")):
            mesh = os.path.join(out_dir, shape + "-" + method + ".off")
            png = os.path.join(out_dir, method + ".png")
            if rows.get(method) and rows[method]["vertices"] != "failed" and os.path.exists(mesh):
                render(mesh, png, view)
                images.append(png)
                titles.append(label)
            print("case %s %s: %s" % (name, method, describe(rows.get(method))))
            table.append((name, method, rows.get(method)))
        panel(images, titles, "case_" + name + ".png", title, 2)
    print("\ncase studies (markdown):")
    print("| case | method | points | seconds | vertex max | Hausdorff | RMS | normal error (deg) | edge distance |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, method, row in table:
        if row is None or row["vertices"] == "failed":
            print("| %s | %s | | failed | | | | | |" % (name, method))
            continue
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, method, row["points"], row["seconds"], row["vertex max"], row["Hausdorff"], row["RMS"],
            row["normal error (deg)"], row["edge distance"]))


if __name__ == "__main__":
    os.makedirs(WORK, exist_ok=True)
    only = os.environ.get("MLS_FIGURES_ONLY", "")
    if not only or "meshes" in only:
        figure7()
    if not only or "cases" in only:
        case_studies()
