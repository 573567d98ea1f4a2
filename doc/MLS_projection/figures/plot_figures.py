#!/usr/bin/env python3
"""Draws the manual's 2D figures from the CSV files written by figures_2d.

    plot_figures.py DATA_DIR FIG_DIR

Run by scripts/figures, with Debian's python3-matplotlib (headless, Agg backend). Prints the
numbers quoted in the manual."""

import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DATA, FIG = sys.argv[1], sys.argv[2]
os.makedirs(FIG, exist_ok=True)
OPS = [("PL_quadratic", r"$\mathcal{P}_L$ (quadratic)", "tab:red"),
       ("PU_quadratic", r"$\mathcal{P}_U$ (quadratic)", "tab:blue"),
       ("PU_wedge", r"$\mathcal{P}_U$ (wedge)", "tab:green")]


def read(name):
    with open(os.path.join(DATA, name)) as f:
        return list(csv.DictReader(f))


def save(fig, name):
    path = os.path.join(FIG, name)
    # Fixed metadata, so that regenerating unchanged figures gives identical files.
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)
    print("wrote", path)


# ------------------------------------------------------------------------------------------
# Figure 2: energy landscapes.
def landscapes():
    rows = read("landscape_grid.csv")
    minima = {float(r["phi_deg"]): r for r in read("landscape_minima.csv")}
    phis = sorted({float(r["phi_deg"]) for r in rows})
    fig, axes = plt.subplots(2, len(phis), figsize=(3.2 * len(phis), 6.6), sharex=True, sharey=True,
                             constrained_layout=True)
    # One colour scale per row (operator), over all the wedges.
    levels = {}
    for key in ("energy_levin_over_h2", "energy_unified_over_h2"):
        v = np.log10(np.array([float(r[key]) for r in rows if r[key] != "nan"]))
        levels[key] = np.linspace(math.floor(v.min() * 10) / 10, math.ceil(v.max() * 10) / 10, 25)
    for col, phi in enumerate(phis):
        sel = [r for r in rows if float(r["phi_deg"]) == phi]
        thetas = sorted({float(r["theta"]) for r in sel})
        rhos = sorted({float(r["rho_over_h"]) for r in sel})
        ti = {t: i for i, t in enumerate(thetas)}
        ri = {t: i for i, t in enumerate(rhos)}
        m = minima[phi]
        for row, (key, label, lib) in enumerate([("energy_levin_over_h2", r"$\mathcal{P}_L$, eq. (1)", "L"),
                                                  ("energy_unified_over_h2", r"$\mathcal{P}_U$ quadratic, eq. (6)", "U")]):
            z = np.full((len(rhos), len(thetas)), np.nan)
            for r in sel:
                z[ri[float(r["rho_over_h"])], ti[float(r["theta"])]] = float(r[key])
            ax = axes[row, col]
            lz = np.log10(np.maximum(z, 1e-8))
            cs = ax.contourf(thetas, rhos, lz, levels=levels[key], cmap="viridis", extend="both")
            ax.contour(thetas, rhos, lz, levels=levels[key][::2], colors="k", linewidths=0.3)
            gt, gr = float(m["grid_theta_" + lib]), float(m["grid_rho_" + lib])
            lt, lr = float(m["lib_theta_" + lib]), float(m["lib_rho_" + lib])
            # theta = -pi/2 and pi/2 are the same frame: mark a minimum there on both sides.
            for t in ([gt, -gt] if abs(abs(gt) - math.pi / 2) < 1e-6 else [gt]):
                ax.plot([t], [gr], "o", ms=11, mfc="none", mec="white", mew=2, clip_on=False)
            for t in ([lt, -lt] if abs(abs(lt) - math.pi / 2) < 1e-3 else [lt]):
                ax.plot([t], [lr], "x", ms=8, color="red", mew=2, clip_on=False)
            emin = np.nanmin(z)
            if row == 0:
                ax.set_title(r"wedge $\phi = %g^\circ$" % phi + "\n" + label + "\nmin %.3g $h^2$" % emin, fontsize=10)
            else:
                ax.set_title(label + "\nmin %.3g $h^2$" % emin, fontsize=10)
                ax.set_xlabel(r"$\theta$ (normal's angle from $(0,1)$)")
            if col == 0:
                ax.set_ylabel(r"$\rho / h$")
            ax.set_xticks([-math.pi / 2, 0, math.pi / 2])
            ax.set_xticklabels([r"$-\pi/2$", "0", r"$\pi/2$"])
            print("landscape phi=%g %s: grid minimum %.4g h^2 at theta=%.3f rho/h=%.3f; library frame theta=%.3f rho/h=%.3f"
                  % (phi, lib, emin, gt, gr, lt, lr)
                  + ("; library energy %s h^2" % m["lib_energy_%s_over_h2" % lib] if "lib_energy_L_over_h2" in m else "")
                  + ("; library origin's tangential offset %s h" % m["lib_tangential_U_over_h"]
                     if lib == "U" and "lib_tangential_U_over_h" in m else ""))
            if col == len(phis) - 1:
                fig.colorbar(cs, ax=axes[row, :], label=r"$\log_{10}$(energy / $h^2$)", shrink=0.9)
    save(fig, "energy_landscapes.png")


def switch():
    rows = read("levin_switch.csv")
    phi = np.array([float(r["phi_deg"]) for r in rows])
    a = np.array([float(r["levin_alignment"]) for r in rows])
    u = np.array([float(r["unified_quadratic_alignment"]) for r in rows])
    low = phi[a < 0.5].max()
    high = phi[(a >= 0.5) & (phi > low)].min()
    fig, ax = plt.subplots(figsize=(7, 3.2), constrained_layout=True)
    ax.plot(phi, a, "-", color="tab:red", label=r"$\mathcal{P}_L$ (plane)")
    ax.plot(phi, u, "--", color="tab:blue", label=r"$\mathcal{P}_U$ (quadratic)")
    ax.axvline(0.5 * (low + high), color="gray", lw=0.8)
    ax.axvline(90, color="gray", lw=0.8, ls=":")
    ax.text(0.5 * (low + high) + 1, 0.5, r"switch at %.2f$^\circ$" % (0.5 * (low + high)), fontsize=9)
    ax.text(91, 0.3, r"paper's bound $\pi/2$", fontsize=9)
    ax.set_xlabel(r"opening angle $\phi$ of the wedge (degrees)")
    ax.set_ylabel(r"$|n \cdot b|$ at the apex")
    ax.legend(loc="lower right")
    save(fig, "levin_switch.png")
    print("switch: P_L frame = bisector up to %g deg, normal along the bisector from %g deg" % (low, high))
    print("P_U quadratic: min |n.b| over all angles %.3g" % u.min())
    bad = phi[u < 0.5]
    if len(bad):
        print("P_U quadratic frame turned (|n.b| < 0.5) at angles:", ", ".join("%g" % x for x in bad))


# ------------------------------------------------------------------------------------------
# Figures 1 and 5: reconstructions with projection paths.
def reconstruction(samples_file, proj_file, true_xy, out, title, path_set, curve_set, xlim, ylim, near,
                   figsize=(15, 5.6), zoom=None, ops=OPS, extra=None):
    samples = read(samples_file)
    h = float(samples[0]["h"])
    sx = [float(r["x"]) for r in samples]
    sy = [float(r["y"]) for r in samples]
    proj = read(proj_file)
    rows = 2 if zoom else 1
    fig, axes = plt.subplots(rows, len(ops), figsize=figsize, constrained_layout=True, squeeze=False,
                             gridspec_kw={"height_ratios": [1, 1.6] if zoom else [1]})
    stats = {}
    for col, (op, label, color) in enumerate(ops):
        for row in range(rows):
            ax = axes[row, col]
            mine = [r for r in proj if r["operator"] == op]
            ax.plot(true_xy[0], true_xy[1], "-", color="0.75", lw=3 if row == 0 else 6, zorder=1)
            for r in mine:
                if r["set"] == path_set:
                    ax.plot([float(r["qx"]), float(r["px"])], [float(r["qy"]), float(r["py"])], "-", color="0.55", lw=0.6,
                            zorder=2)
            ax.plot(sx, sy, ".", color="k", ms=3, zorder=3)
            pts = [r for r in mine if r["set"] == curve_set and r["success"] == "1"]
            ax.plot([float(r["px"]) for r in pts], [float(r["py"]) for r in pts], "o", ms=2.5, color=color, zorder=4)
            feat = [r for r in mine if r["on_feature"] == "1"]
            if feat:
                ax.plot([float(r["px"]) for r in feat], [float(r["py"]) for r in feat], "*", ms=9, color="orange",
                        mec="k", mew=0.5, zorder=5)
            d = np.array([float(r["distance"]) for r in mine if r["success"] == "1"]) / h
            dn = np.array([float(r["distance"]) for r in mine if r["success"] == "1" and near(r)]) / h
            fails = sum(r["success"] == "0" for r in mine)
            statuses = defaultdict(int)
            for r in mine:
                statuses[r.get("status", "?")] += 1
            far = int(np.sum(d > 0.5))
            stats[op] = (d.max(), np.sqrt(np.mean(d ** 2)), dn.max() if len(dn) else float("nan"), fails, len(feat),
                         len(mine), far, dict(statuses), np.median(d))
            ax.set_aspect("equal")
            if extra:
                extra(ax)
            if row == 0:
                ax.set_title("%s\nmax %.3f h, RMS %.3f h" % (label, d.max(), np.sqrt(np.mean(d ** 2))), fontsize=11)
                ax.set_xlim(*xlim)
                ax.set_ylim(*ylim)
                if zoom:
                    ax.add_patch(plt.Rectangle((zoom[0][0], zoom[1][0]), zoom[0][1] - zoom[0][0], zoom[1][1] - zoom[1][0],
                                               fill=False, ec="k", lw=1))
            else:
                ax.set_title("close-up of the box: max %.3f h near the corner" % stats[op][2], fontsize=10)
                ax.set_xlim(*zoom[0])
                ax.set_ylim(*zoom[1])
    fig.suptitle(title, fontsize=12)
    save(fig, out)
    for op, s in stats.items():
        print("%s %s: %d projections, max %.4g h, RMS %.4g h, median %.3g h, max near the corner %.4g h, "
              "%d beyond 0.5 h, failed %d, on a feature %d, statuses %s"
              % (out, op, s[5], s[0], s[1], s[8], s[2], s[6], s[3], s[4], s[7]))
    return stats


def wedge_reconstruction():
    samples = read("wedge_samples.csv")
    h = float(samples[0]["h"])
    phi = math.radians(50)
    t = np.array([1, 0, 1])
    true_xy = (t * np.array([-math.sin(phi / 2), 0, math.sin(phi / 2)]), t * math.cos(phi / 2))
    reconstruction("wedge_samples.csv", "wedge_projections.csv", true_xy, "wedge_reconstruction.png",
                   r"Noiseless wedge, $\phi = 50^\circ$, spacing 0.02, $h$ = %.3f: queries within 1.5$h$ "
                   r"(grey: query $\to$ projection)" % h, "grid", "grid", (-0.45, 0.45), (-0.15, 0.8),
                   lambda r: math.hypot(float(r["qx"]), float(r["qy"])) < 3 * h)


def curve_reconstruction():
    samples = read("curve_samples.csv")
    h = float(samples[0]["h"])
    true = read("curve_true.csv")
    xs, ys = [], []
    for r in true:  # the two arcs, separated by a NaN (the file jumps from the last corner back)
        x, y = float(r["x"]), float(r["y"])
        if xs and math.hypot(x - xs[-1], y - ys[-1]) > 0.1:
            xs.append(float("nan"))
            ys.append(float("nan"))
        xs.append(x)
        ys.append(y)
    true_xy = (xs, ys)
    xc = 0.8
    reconstruction("curve_samples.csv", "curve_projections.csv", true_xy, "curve_reconstruction.png",
                   r"Noisy ($\sigma$ = 0.01), irregular sampling (%d points) of a lens with %.1f$^\circ$ corners, "
                   r"$h$ = %.3f; grey: paths of the samples' projections" % (len(samples), float(samples[0]["corner_angle_deg"]), h),
                   "samples", "band", (-0.9, 0.9), (-0.48, 0.48),
                   lambda r: min(math.hypot(float(r["qx"]) - s, float(r["qy"])) for s in (-xc, xc)) < 3 * h,
                   figsize=(16, 8.2), zoom=((0.45, 0.85), (-0.2, 0.2)))


# ------------------------------------------------------------------------------------------
# Figure 4: the collapse region of the apex.
def collapse():
    rows = read("collapse_region.csv")
    phis = sorted({float(r["phi_deg"]) for r in rows}, reverse=True)
    fig, axes = plt.subplots(1, len(phis), figsize=(6 * len(phis), 7.2), constrained_layout=True)
    for ax, phi in zip(axes, phis):
        sel = [r for r in rows if float(r["phi_deg"]) == phi]
        h = float(sel[0]["h"])

        def on_apex(r):
            return math.hypot(float(r["px_over_h"]), float(r["py_over_h"])) * h < 1e-9

        a = [r for r in sel if on_apex(r)]
        b = [r for r in sel if not on_apex(r) and r["success"] == "1"]
        f = [r for r in sel if r["success"] != "1"]
        ax.plot([float(r["qx_over_h"]) for r in b], [float(r["qy_over_h"]) for r in b], ".", color="0.7", ms=4,
                label="projected elsewhere")
        ax.plot([float(r["qx_over_h"]) for r in a], [float(r["qy_over_h"]) for r in a], "s", color="tab:red", ms=3.5,
                label="projected onto the apex")
        if f:
            ax.plot([float(r["qx_over_h"]) for r in f], [float(r["qy_over_h"]) for r in f], "x", color="k", ms=4,
                    label="failed (status not a success)")
        circle = np.linspace(0, 2 * math.pi, 200)
        ax.plot(2.5 * np.cos(circle), 2.5 * np.sin(circle), ":", color="tab:blue", lw=1.2,
                label=r"2.5$h$ from the apex (weight support)")
        p = math.radians(phi)
        for s in (-1, 1):
            ray = np.array([s * math.sin(p / 2), math.cos(p / 2)])
            ax.plot([0, 3.5 * ray[0]], [0, 3.5 * ray[1]], "k-", lw=2.5)
            nrm = np.array([ray[1], -ray[0]]) * s  # the normal of the ray on the reflex side
            ax.plot([0, 4.5 * nrm[0]], [0, 4.5 * nrm[1]], "k--", lw=1)
        cone = [r for r in sel if r["in_cone"] == "1"]
        out = [r for r in sel if r["in_cone"] == "0"]
        ca = sum(on_apex(r) for r in cone)
        oa = sum(on_apex(r) for r in out)
        cf = sum(r["success"] != "1" for r in cone)
        near = [r for r in cone if math.hypot(float(r["qx_over_h"]), float(r["qy_over_h"])) <= 2]
        near_on = sum(on_apex(r) for r in near)
        ax.set_title(r"$\phi = %g^\circ$: %d of %d queries in the apex's normal cone land on it" % (phi, ca, len(cone))
                     + "\n(%d of %d within 2$h$ of the apex), %d of %d outside the cone" % (near_on, len(near), oa, len(out)),
                     fontsize=11)
        ax.set_xlim(-3.1, 3.1)
        ax.set_ylim(-3.1, 3.1)
        ax.set_aspect("equal")
        ax.set_xlabel("x / h")
        ax.set_ylabel("y / h")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=2, fontsize=9)
        missed = [r for r in cone if not on_apex(r) and r["success"] == "1"]
        dmin = min((math.hypot(float(r["qx_over_h"]), float(r["qy_over_h"])) for r in missed), default=float("nan"))
        print("collapse phi=%g: %d/%d cone queries on the apex (%d/%d within 2h), %d failed, %d projected elsewhere "
              "(the nearest %.2f h from the apex), %d/%d outside the cone on the apex"
              % (phi, ca, len(cone), near_on, len(near), cf, len(missed), dmin, oa, len(out)))
        failed = [r for r in sel if r["success"] != "1"]
        if failed:  # in the cone, the nearest point of the wedge (and sample) is the apex
            print("  failed queries: %d, all in the cone: %s, nearest to the apex %.2f h"
                  % (len(failed), all(r["in_cone"] == "1" for r in failed),
                     min(math.hypot(float(r["qx_over_h"]), float(r["qy_over_h"])) for r in failed)))
        for r in out:
            if on_apex(r):
                print("  outside the cone, on the apex: q/h=(%s, %s)" % (r["qx_over_h"], r["qy_over_h"]))
    save(fig, "collapse_region.png")


def gap_completion():
    samples = read("gap_samples.csv")
    h, gap = float(samples[0]["h"]), float(samples[0]["gap"])
    phi = math.radians(70)
    t = np.array([1, 0, 1])
    true_xy = (t * np.array([-math.sin(phi / 2), 0, math.sin(phi / 2)]), t * math.cos(phi / 2))

    def gap_circle(ax):
        ax.add_patch(plt.Circle((0, 0), gap, fill=False, ls="--", ec="0.4", lw=0.8, zorder=1))

    stats = reconstruction("gap_samples.csv", "gap_projections.csv", true_xy, "gap_completion.png",
                           r"Wedge of $70^\circ$ without samples within %.2g of its apex (dashed), $h$ = %.3g: queries "
                           r"within $h$ (grey: query $\to$ projection)" % (gap, h), "grid", "grid", (-0.3, 0.3),
                           (-0.12, 0.36), lambda r: math.hypot(float(r["qx"]), float(r["qy"])) < gap + h,
                           figsize=(11, 5.2), ops=OPS[1:], extra=gap_circle)
    # Where the reconstruction crosses the bisector: the projections of the queries on the bisector
    # below the apex (outside the wedge), whose closest point on the true wedge is the apex.
    proj = read("gap_projections.csv")
    for op, _, _ in OPS[1:]:
        below = [r for r in proj if r["operator"] == op and r["set"] == "bisector" and float(r["qy"]) <= 0]
        apex = [math.hypot(float(r["px"]), float(r["py"])) / h for r in below]
        print("gap_completion %s: %d bisector queries below the apex projected within %.3g h to %.3g h of the apex"
              % (op, len(apex), min(apex), max(apex)))
    return stats


def thumbnail():
    # The package's picture: the wedge reconstructions of P_L and P_U (wedge), small.
    proj = read("wedge_projections.csv")
    fig, axes = plt.subplots(1, 2, figsize=(1.8, 1.2), dpi=100)
    for ax, op, color in zip(axes, ["PL_quadratic", "PU_wedge"], ["tab:red", "tab:green"]):
        pts = [r for r in proj if r["operator"] == op]
        ax.plot([float(r["px"]) for r in pts], [float(r["py"]) for r in pts], ".", ms=1.5, color=color)
        ax.set_xlim(-0.3, 0.3)
        ax.set_ylim(-0.1, 0.6)
        ax.set_aspect("equal")
        ax.axis("off")
    fig.subplots_adjust(0, 0, 1, 1, 0, 0)
    save(fig, "mls_projection.png")


if __name__ == "__main__":
    only = os.environ.get("MLS_FIGURES_ONLY", "")
    steps = [("landscape", landscapes), ("switch", switch), ("wedge", wedge_reconstruction),
             ("curve", curve_reconstruction), ("collapse", collapse), ("wedge", thumbnail), ("gap", gap_completion)]
    for name, fn in steps:
        if not only or name in only:
            fn()
