"""The manual's colour figure: the coloured built-in solid (11810 points, colours from the exact
normals, no normals given) meshed by mls_mesh with its defaults, the colours carried by the local
fits (a PLY mesh), and by CGAL's Poisson reconstruction (poisson_mesh), whose vertices take the
colour of their nearest input point, rendered side by side.

    figure_colours.py COLOURED_SOLID BIN RENDER_MESH WORK_DIR FIG_DIR

COLOURED_SOLID: the program writing the coloured points; BIN: the directory of mls_mesh and
poisson_mesh. Prints mls_mesh's summary line.
"""
import subprocess
import sys
import os
import numpy as np
from scipy.spatial import cKDTree
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

solid_program, bin_dir, render, work, fig_dir = sys.argv[1:6]
os.makedirs(work, exist_ok=True)
ply = os.path.join(work, "coloured_solid.ply")
subprocess.run([solid_program, ply], check=True)


def read_ply_vertices(path, columns):
    with open(path) as f:
        lines = f.read().split("\n")
    n = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
    start = lines.index("end_header") + 1
    return np.array([[float(x) for x in l.split()[:columns]] for l in lines[start:start + n]])


def read_off(path):
    words = open(path).read().split()
    nv, nf = int(words[1]), int(words[2])
    width = 7 if words[0] == "COFF" else 3
    v = np.array(words[4:4 + width * nv], dtype=float).reshape(nv, width)
    f = np.array(words[4 + width * nv:], dtype=int).reshape(nf, 4)[:, 1:]
    return v, f


def write_coff(path, v, colours, f):
    with open(path, "w") as out:
        out.write("COFF\n%d %d 0\n" % (len(v), len(f)))
        for p, c in zip(v, colours):
            out.write("%.17g %.17g %.17g %d %d %d 255\n" % (p[0], p[1], p[2], c[0], c[1], c[2]))
        for t in f:
            out.write("3 %d %d %d\n" % tuple(t))


points = read_ply_vertices(ply, 6)
xyz, rgb = points[:, :3], points[:, 3:6]
np.savetxt(os.path.join(work, "coloured_solid.xyz"), xyz, fmt="%.17g")
tree = cKDTree(xyz)

mls_off = os.path.join(work, "mls.off")
run = subprocess.run([os.path.join(bin_dir, "mls_mesh"), "--input", ply, "--output", mls_off, "--quiet"],
                     stderr=subprocess.PIPE, text=True, check=True)
print(run.stderr.strip().split("\n")[-1])
poisson_raw = os.path.join(work, "poisson.off")
subprocess.run([os.path.join(bin_dir, "poisson_mesh"), os.path.join(work, "coloured_solid.xyz"), poisson_raw], check=True)
pv, pf = read_off(poisson_raw)
poisson_colours = rgb[tree.query(pv[:, :3])[1]]
poisson_off = os.path.join(work, "poisson_coloured.off")
write_coff(poisson_off, pv[:, :3], poisson_colours, pf)

views = [(25, -60), (-20, 150)]
images = []
for name, mesh in (("mls", mls_off), ("poisson", poisson_off)):
    for k, view in enumerate(views):
        png = os.path.join(work, "%s_%d.png" % (name, k))
        subprocess.run([render, mesh, png, "--view", "%g,%g" % view, "--size", "900", "--no-edges"], check=True)
        images.append(plt.imread(png))

def crop(image):
    """The image without its white margins."""
    ink = np.argwhere(image[:, :, :3].min(axis=2) < 0.99)
    (top, left), (bottom, right) = ink.min(axis=0), ink.max(axis=0) + 1
    return image[top:bottom, left:right]


images = [crop(image) for image in images]
fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
titles = ["MLS (unified operator, mixed space): colours from the local fits",
          "CGAL's Poisson: colour of the nearest input point"]
for row in range(2):
    for col in range(2):
        ax = axes[col][row]
        image = images[2 * row + col]
        ax.imshow(image)
        ax.set_axis_off()
        if col == 0:
            ax.set_title(titles[row], fontsize=12)
fig.tight_layout()
out = os.path.join(fig_dir, "colours.png")
fig.savefig(out, dpi=80)
print("wrote", out)
