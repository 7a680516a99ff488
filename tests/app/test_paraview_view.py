#!/usr/bin/env python3
"""scripts/paraview_screenshot.py's camera frame, without ParaView: up against the run's gravity,
the front turned with the scene (a Y-up scene written as the Z-up one turned by x, y, z -> x, z, -y
is seen from where the Z-up one is), read from DIR/run.json beside DIR/vtk/.

usage: test_paraview_view.py SOURCE_DIR SCRATCH_DIR"""
import json
import math
import os
import random
import sys
import types

SOURCE, SCRATCH = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import paraview_screenshot as shot  # noqa: E402  (imports no ParaView until main())

failures = []
TOL = 1e-12   # rotations of unit vectors in doubles: round-off only


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def close(u, v):
    return max(abs(a - b) for a, b in zip(u, v)) < TOL


# a Z-up scene: seen from -y with z up, as before
up, front = shot.view_frame([0.0, 0.0, -9.81])
check(close(up, [0, 0, 1]) and close(front, [0, -1, 0]), "Z-up: up z, front -y, got %s %s" % (up, front))
# the same scene turned to Y-up (x, y, z -> x, z, -y): -y goes to +z
up, front = shot.view_frame([0.0, -9.81, 0.0])
check(close(up, [0, 1, 0]) and close(front, [0, 0, 1]), "Y-up: up y, front +z, got %s %s" % (up, front))
# upside down: the half turn about y, as the replay's (front stays -y)
up, front = shot.view_frame([0.0, 0.0, 9.81])
check(close(up, [0, 0, -1]) and close(front, [0, -1, 0]), "upside down: got %s %s" % (up, front))

# any gravity: the turn is a rotation taking z onto up, and the front is square to up
rng = random.Random(7)
for _ in range(200):
    g = [rng.uniform(-1, 1) for _ in range(3)]
    n = math.sqrt(sum(x * x for x in g))
    if n < 1e-3:
        continue
    up, front = shot.view_frame(g)
    r = shot.turn_from_z(up)
    rows_ok = all(abs(sum(r[i][k] * r[j][k] for k in range(3)) - (1.0 if i == j else 0.0)) < 1e-12
                  for i in range(3) for j in range(3))
    det = (r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
           + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]))
    check(rows_ok and abs(det - 1.0) < 1e-12, "gravity %s: the turn is not a rotation" % g)
    check(close([r[i][2] for i in range(3)], up), "gravity %s: z not taken onto up" % g)
    check(close(up, [-x / n for x in g]), "gravity %s: up is not against it" % g)
    check(abs(sum(a * b for a, b in zip(up, front))) < 1e-12, "gravity %s: front not square to up" % g)

# the gravity of DIR/run.json beside DIR/vtk/SCENE.pvd, --up over it, z without either
run_dir = os.path.join(SCRATCH, "paraview_view")
os.makedirs(os.path.join(run_dir, "vtk"), exist_ok=True)
with open(os.path.join(run_dir, "run.json"), "w") as f:
    json.dump({"parameters": {"gravity": [0.0, -9.81, 0.0]}}, f)
pvd = os.path.join(run_dir, "vtk", "scene.pvd")
args = types.SimpleNamespace(pvd=pvd, up=None)
check(close(shot.scene_up(args), [0.0, -9.81, 0.0]), "run.json's gravity not read: %s" % shot.scene_up(args))
args.up = "1,0,0"
check(close(shot.scene_up(args), [-1.0, 0.0, 0.0]), "--up not taken: %s" % shot.scene_up(args))
args = types.SimpleNamespace(pvd=os.path.join(SCRATCH, "nowhere", "vtk", "x.pvd"), up=None)
check(close(shot.scene_up(args), [0.0, 0.0, -1.0]), "without run.json, not z up: %s" % shot.scene_up(args))

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
