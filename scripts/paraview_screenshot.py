#!/usr/bin/env pvpython
"""A picture of a cairn run's VTK output (cairn run ... --vtk) at one time, made by ParaView.

The blocks (DIR/vtk/SCENE.pvd) are coloured by the speed of their centre of mass (the cells'
`velocity` field, m/s) and the contact points (DIR/vtk/SCENE_contacts.pvd, beside it) are drawn as
arrows along their normal force, of a length proportional to it. Run with ParaView's Python:

    xvfb-run -a pvpython scripts/paraview_screenshot.py runs/wall/vtk/wall.pvd wall.png --time 2.5
    pvpython --force-offscreen-rendering scripts/paraview_screenshot.py ...   (offscreen builds)

docs/visualisation.md describes the files and the options.
"""
import argparse
import json
import math
import os
import sys


def arguments():
    p = argparse.ArgumentParser(description="save a PNG of a cairn --vtk time series at one time")
    p.add_argument("pvd", help="the blocks' series, DIR/vtk/SCENE.pvd")
    p.add_argument("png", help="the picture to write")
    p.add_argument("--time", type=float, default=None,
                   help="s; the sample nearest to it (default: the last sample)")
    p.add_argument("--contacts", default=None,
                   help="the contacts' series (default: SCENE_contacts.pvd beside the blocks'; "
                        "'none' draws no forces)")
    p.add_argument("--arrow", type=float, default=None,
                   help="m per N of normal force (default: the largest force as long as a fifth "
                        "of the scene's diagonal)")
    p.add_argument("--size", default="1200x800", help="picture size in pixels, WIDTHxHEIGHT")
    p.add_argument("--azimuth", type=float, default=-35.0,
                   help="deg, camera turned about the up axis from the front (-y in a Z-up scene)")
    p.add_argument("--elevation", type=float, default=20.0, help="deg, camera raised above the ground")
    p.add_argument("--up", default=None,
                   help="x,y,z: the scene's up (default: against the gravity of DIR/run.json, "
                        "else z)")
    p.add_argument("--opacity", type=float, default=0.4, help="of the blocks, 0 to 1 (default 0.4)")
    p.add_argument("--speed-range", type=float, default=None,
                   help="m/s at the top of the colour scale (default: the largest speed at that time)")
    return p.parse_args()


def turn_from_z(up):
    """the rotation (3 rows) taking z onto the unit vector up by the shortest turn; the half turn
    of an upside-down scene about y, as the 3-D replay's (three.js setFromUnitVectors)"""
    c = up[2]   # cos of the turn: z·up
    if c < -1.0 + 1e-12:
        return [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]
    k = [-up[1], up[0], 0.0]   # z × up: axis times sin
    f = 1.0 / (1.0 + c)       # Rodrigues: R = I + [k]x + [k]x²/(1 + c)
    kx = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]]
    kx2 = [[sum(kx[i][m] * kx[m][j] for m in range(3)) for j in range(3)] for i in range(3)]
    return [[(1.0 if i == j else 0.0) + kx[i][j] + f * kx2[i][j] for j in range(3)] for i in range(3)]


def view_frame(gravity):
    """(up, front): up against gravity (m/s², any length; z when zero) and the unit vector from the
    scene's centre towards the camera before the azimuth and elevation: -y for a Z-up scene, turned
    with the scene otherwise (a Y-up scene is seen from +z)"""
    norm = math.sqrt(sum(g * g for g in gravity))
    up = [0.0, 0.0, 1.0] if not norm > 0.0 else [-g / norm for g in gravity]
    r = turn_from_z(up)
    front = [-r[i][1] for i in range(3)]   # R·(−y)
    return up, front


def scene_up(a):
    """the up vector: --up, else against the gravity in the run's run.json (DIR/vtk/SCENE.pvd ->
    DIR/run.json), else z"""
    if a.up is not None:
        try:
            up = [float(x) for x in a.up.split(",")]
        except ValueError:
            up = []
        if len(up) != 3 or not math.sqrt(sum(u * u for u in up)) > 0.0:
            sys.exit("--up %r: expected x,y,z, not all zero, e.g. 0,1,0" % a.up)
        return [-u for u in up]   # as a gravity
    run_json = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(a.pvd))), "run.json")
    try:
        with open(run_json) as f:
            gravity = json.load(f)["parameters"]["gravity"]
        if len(gravity) == 3:
            return [float(g) for g in gravity]
    except (OSError, ValueError, KeyError, TypeError):
        pass
    return [0.0, 0.0, -1.0]


def nearest(times, t):
    """the sample time of the series nearest to t (the last one when t is None)"""
    if not times:
        return 0.0
    if t is None:
        return times[-1]
    return min(times, key=lambda x: abs(x - t))


def main():
    a = arguments()
    from paraview import simple as pv   # here: view_frame is usable without ParaView (tests)
    try:
        width, height = (int(x) for x in a.size.lower().split("x"))
    except ValueError:
        sys.exit("--size %r: expected WIDTHxHEIGHT, e.g. 1200x800" % a.size)
    if not os.path.isfile(a.pvd):
        sys.exit("%s: no such file" % a.pvd)
    contacts_file = a.contacts
    if contacts_file is None:
        stem, _ = os.path.splitext(a.pvd)
        contacts_file = stem + "_contacts.pvd"
    if contacts_file == "none" or not os.path.isfile(contacts_file):
        contacts_file = None

    blocks = pv.PVDReader(FileName=a.pvd)
    t = nearest(list(blocks.TimestepValues or []), a.time)
    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = t
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0   # ParaView >= 5.10: keep the white background
    except AttributeError:
        pass
    blocks.UpdatePipeline(t)

    shown = pv.Show(blocks, view)
    shown.Representation = "Surface With Edges"
    shown.EdgeColor = [0.2, 0.2, 0.2]
    shown.Opacity = a.opacity   # see the forces inside the joints
    pv.ColorBy(shown, ("CELLS", "velocity", "Magnitude"))
    lut = pv.GetColorTransferFunction("velocity")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    top = a.speed_range
    if top is None:
        low, top = blocks.CellData["velocity"].GetRange(-1)
    lut.RescaleTransferFunction(0.0, max(top, 1e-6))
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "speed [m/s]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    shown.SetScalarBarVisibility(view, True)

    # the scene's size sets the default arrow scale
    (x0, x1, y0, y1, z0, z1) = blocks.GetDataInformation().GetBounds()
    diagonal = math.sqrt((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2)

    if contacts_file:
        contacts = pv.PVDReader(FileName=contacts_file)
        contacts.UpdatePipeline(t)
        forces = contacts.PointData["normal_force"]
        largest = forces.GetRange(-1)[1] if forces is not None else 0.0
        if largest > 0.0:
            arrows = pv.Glyph(Input=contacts, GlyphType="Arrow")
            arrows.OrientationArray = ["POINTS", "normal_force"]
            arrows.ScaleArray = ["POINTS", "normal_force"]
            arrows.ScaleFactor = a.arrow if a.arrow is not None else 0.2 * diagonal / largest
            arrows.GlyphMode = "All Points"
            drawn = pv.Show(arrows, view)
            drawn.ColorArrayName = ["POINTS", ""]   # one solid colour
            drawn.AmbientColor = drawn.DiffuseColor = [0.85, 0.1, 0.1]

    what = "   arrows: normal contact forces" if contacts_file else ""
    label = pv.Text(Text="t = %.3f s%s" % (t, what))
    text = pv.Show(label, view)
    text.WindowLocation = "Upper Left Corner"
    text.Color = [0.1, 0.1, 0.1]
    text.FontSize = 14

    # a view from the front (-y in a Z-up scene), up against gravity, turned and raised, the
    # scene filling the picture
    up, front = view_frame(scene_up(a))
    camera = view.GetActiveCamera()
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*[centre[i] + 3.0 * diagonal * front[i] for i in range(3)])
    camera.SetViewUp(*up)
    camera.Azimuth(a.azimuth)
    camera.Elevation(a.elevation)
    view.ResetCamera(False)
    pv.Render(view)
    pv.SaveScreenshot(a.png, view, ImageResolution=[width, height])
    print("%s: t = %.3f s" % (a.png, t))


if __name__ == "__main__":
    main()
