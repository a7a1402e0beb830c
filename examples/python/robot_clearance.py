"""Clearance of a robot arm along a trajectory, with prox's batch API.

    python robot_clearance.py clearance.png [--urdf arm.urdf] [--steps 200]

The arm (arm.urdf next to this file) is read with yourdfpy, which does the forward kinematics. Each
collision primitive of each link is placed in the world frame and converted to a prox shape:

    URDF <cylinder radius r length h>, pose (R, o): centred on o along R's z column
        -> RCC(base = o - h/2 z, axis = h z, r)
    URDF <box size s>, pose (R, o): centred on o
        -> BOX(corner = o - R s/2, edges = R[:, i] * s[i])
    URDF <sphere radius r>, pose (R, o) -> SPH(o, r)

The pairs watched are every primitive of two links not joined by a joint (a joint's two links touch
by construction) and every primitive of a moving link against two obstacles: a table (a BOX turned
about z) and a pillar (an RCC). All configurations of the trajectory go to prox in one call per kind
pair (RCC-RCC, RCC-BOX, ...), N = steps x pairs of that kind: prox.distance runs the whole batch in C
on all cores. The minimum clearance, its witness points and a plot of clearance against time
(matplotlib, Agg backend) are the output.
"""

import argparse
import os
import sys
from collections import defaultdict

import numpy as np

import prox

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_URDF = os.path.join(HERE, "arm.urdf")
DURATION = 8.0  # seconds of trajectory


def trajectory(steps):
    """Times (steps,) and joint configurations (steps, 4): the arm swings from the pillar's side over
    the table, reaches down towards it, and folds back. Smooth (sums of cosines), inside the limits."""
    t = np.linspace(0.0, DURATION, steps)
    s = 0.5 - 0.5 * np.cos(np.pi * t / DURATION)       # 0 -> 1, eased
    bump = np.sin(np.pi * t / DURATION) ** 2          # 0 -> 1 -> 0
    q = np.empty((steps, 4))
    q[:, 0] = 1.45 - 1.75 * s                         # base yaw: towards the pillar, then the table
    q[:, 1] = 0.25 + 0.80 * bump                      # shoulder pitches forward
    q[:, 2] = 0.35 + 0.85 * bump                      # elbow folds down towards the table top
    q[:, 3] = 0.2 + 0.6 * np.sin(2.0 * np.pi * t / DURATION)  # wrist nods
    return t, q


def obstacles():
    """The fixed scene: name -> (kind, parameters) in the world frame."""
    yaw = np.radians(20.0)
    c, s = np.cos(yaw), np.sin(yaw)
    ex = np.array([c, s, 0.0]) * 0.60                 # table: 0.60 x 0.90 x 0.28 block
    ey = np.array([-s, c, 0.0]) * 0.90
    ez = np.array([0.0, 0.0, 0.28])
    centre = np.array([0.78, -0.20, 0.14])
    table = ("BOX", dict(corner=centre - 0.5 * (ex + ey + ez), e1=ex, e2=ey, e3=ez))
    pillar = ("RCC", dict(base=np.array([0.05, 0.80, 0.0]), axis=np.array([0.0, 0.0, 1.40]), radius=0.07))
    return {"table": table, "pillar": pillar}


def load_primitives(urdf):
    """Every collision primitive of the robot: list of (link, index, kind, geometry, origin 4x4)."""
    prims = []
    for link in urdf.robot.links:
        for i, col in enumerate(link.collisions):
            g = col.geometry
            origin = np.eye(4) if col.origin is None else np.asarray(col.origin, dtype=float)
            if g.cylinder is not None:
                prims.append((link.name, i, "RCC", g.cylinder, origin))
            elif g.box is not None:
                prims.append((link.name, i, "BOX", g.box, origin))
            elif g.sphere is not None:
                prims.append((link.name, i, "SPH", g.sphere, origin))
            else:
                raise ValueError(f"link {link.name}: only box, cylinder and sphere collisions convert exactly")
    return prims


def to_world(kind, geom, pose):
    """The prox parameters of one primitive for a stack of world poses (T, 4, 4)."""
    R, o = pose[:, :3, :3], pose[:, :3, 3]
    if kind == "RCC":
        h, z = geom.length, R[:, :, 2]
        return dict(base=o - 0.5 * h * z, axis=h * z, radius=np.full(len(o), geom.radius))
    if kind == "BOX":
        size = np.asarray(geom.size, dtype=float)
        e = R * size                                  # column i of R scaled by size[i]
        return dict(corner=o - 0.5 * e.sum(axis=2), e1=e[:, :, 0], e2=e[:, :, 1], e3=e[:, :, 2])
    return dict(center=o, radius=np.full(len(o), geom.radius))


def world_primitives(urdf, q):
    """Name -> (kind, parameters as (T, ...) arrays) for every primitive over the trajectory q."""
    prims = load_primitives(urdf)
    poses = {p[0]: np.empty((len(q), 4, 4)) for p in prims}
    for k, cfg in enumerate(q):
        urdf.update_cfg(cfg)
        for link in poses:
            poses[link][k] = urdf.get_transform(link)
    out = {}
    for link, i, kind, geom, origin in prims:
        out[f"{link}/{kind.lower()}{i}"] = (kind, to_world(kind, geom, poses[link] @ origin))
    return out


def watched_pairs(urdf, prims, obst):
    """The pairs to watch: primitives of non-adjacent links, and moving links against obstacles."""
    adjacent = {frozenset((j.parent, j.child)) for j in urdf.robot.joints}
    base = urdf.base_link
    names = list(prims)
    link = {n: n.split("/")[0] for n in names}
    pairs = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if link[a] != link[b] and frozenset((link[a], link[b])) not in adjacent:
                pairs.append((a, b, "self"))
    for a in names:
        if link[a] != base:                           # the pedestal does not move: its clearance is constant
            for b in obst:
                pairs.append((a, b, "obstacle"))
    return pairs


def make_shapes(kind, params):
    """A prox shape batch from a list of parameter dicts (each (T, ...) arrays), concatenated."""
    cat = {k: np.concatenate([p[k] for p in params]) for k in params[0]}
    if kind == "RCC":
        return prox.RCC(cat["base"], cat["axis"], cat["radius"])
    if kind == "BOX":
        return prox.BOX(cat["corner"], cat["e1"], cat["e2"], cat["e3"])
    return prox.SPH(cat["center"], cat["radius"])


def clearances(shapes, pairs, steps):
    """Distance, witness points and intersect flag of every pair at every step: (P, T), (P, T, 3) x 2,
    (P, T). One prox.distance call per kind pair: all pairs of that kind at all steps together."""
    P = len(pairs)
    dist = np.empty((P, steps))
    p1 = np.empty((P, steps, 3))
    p2 = np.empty((P, steps, 3))
    hit = np.empty((P, steps), dtype=bool)
    groups = defaultdict(list)
    for k, (a, b, _) in enumerate(pairs):
        groups[(shapes[a][0], shapes[b][0])].append(k)
    for (ka, kb), ks in groups.items():
        A = make_shapes(ka, [shapes[pairs[k][0]][1] for k in ks])
        B = make_shapes(kb, [shapes[pairs[k][1]][1] for k in ks])
        r = prox.distance(A, B, errors="raise")
        dist[ks] = r.distance.reshape(len(ks), steps)
        p1[ks] = r.p1.reshape(len(ks), steps, 3)
        p2[ks] = r.p2.reshape(len(ks), steps, 3)
        hit[ks] = r.intersect.reshape(len(ks), steps)
    return dist, p1, p2, hit


def plot(png, t, dist, pairs, k_min, step_min):
    """Clearance against time: the minimum over self pairs, over obstacle pairs, and every pair thin."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    kinds = np.array([p[2] for p in pairs])
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=110)
    for k in range(len(pairs)):
        ax.plot(t, 100 * dist[k], color="0.85", lw=0.6, zorder=1)
    ax.plot(t, 100 * dist[kinds == "self"].min(axis=0), lw=2, label="between links (non-adjacent)")
    ax.plot(t, 100 * dist[kinds == "obstacle"].min(axis=0), lw=2, label="to obstacles (table, pillar)")
    a, b, _ = pairs[k_min]
    ax.plot(t[step_min], 100 * dist[k_min, step_min], "kv", ms=8,
            label=f"minimum {100 * dist[k_min, step_min]:.2f} cm: {a} - {b}")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("clearance [cm]")
    ax.set_ylim(0, max(40.0, 100 * np.median(dist.min(axis=0)) * 2.5))
    ax.set_title("Arm clearance along the trajectory (prox.distance, one batch per kind pair)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


def run(png=None, urdf_path=DEFAULT_URDF, steps=200):
    """Runs the example; returns a dict with the arrays (for tests) and writes the plot when png is set."""
    import yourdfpy

    urdf = yourdfpy.URDF.load(urdf_path, load_meshes=False, build_collision_scene_graph=False)
    t, q = trajectory(steps)
    shapes = world_primitives(urdf, q)
    obst = obstacles()
    pairs = watched_pairs(urdf, shapes, obst)
    for name, (kind, par) in obst.items():         # the obstacles do not move: repeat them over time
        shapes[name] = (kind, {k: np.broadcast_to(v, (steps,) + np.shape(v)) for k, v in par.items()})
    dist, p1, p2, hit = clearances(shapes, pairs, steps)
    k_min, step_min = np.unravel_index(np.argmin(dist), dist.shape)
    if png:
        plot(png, t, dist, pairs, k_min, step_min)
    return dict(t=t, q=q, shapes=shapes, pairs=pairs, distance=dist, p1=p1, p2=p2, intersect=hit,
                k_min=int(k_min), step_min=int(step_min))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("png", help="where to write the plot of clearance against time")
    ap.add_argument("--urdf", default=DEFAULT_URDF, help="robot description (default: arm.urdf here)")
    ap.add_argument("--steps", type=int, default=200, help="configurations along the trajectory")
    args = ap.parse_args(argv)
    out = run(args.png, args.urdf, args.steps)
    dist, pairs = out["distance"], out["pairs"]
    k, s = out["k_min"], out["step_min"]
    a, b, what = pairs[k]
    n_hit = int(out["intersect"].any(axis=1).sum())
    print(f"{len(pairs)} pairs x {args.steps} configurations = {dist.size} prox queries")
    for kind in ("self", "obstacle"):
        sel = [i for i, p in enumerate(pairs) if p[2] == kind]
        i, j = np.unravel_index(np.argmin(dist[sel]), (len(sel), args.steps))
        print(f"min clearance {kind:8s} {100 * dist[sel][i, j]:8.3f} cm  at t = {out['t'][j]:.2f} s: "
              f"{pairs[sel[i]][0]} - {pairs[sel[i]][1]}")
    print(f"MIN CLEARANCE {dist[k, s]:.6f} m at t = {out['t'][s]:.3f} s (step {s}) between {a} and {b} ({what})")
    print(f"  witness on {a}: {np.array2string(out['p1'][k, s], precision=5)}")
    print(f"  witness on {b}: {np.array2string(out['p2'][k, s], precision=5)}")
    if n_hit:
        print(f"WARNING: {n_hit} pairs intersect somewhere along the trajectory")
    print(f"plot: {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
