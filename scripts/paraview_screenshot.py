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
import math
import os
import sys

from paraview import simple as pv


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
    p.add_argument("--azimuth", type=float, default=-35.0, help="deg, camera turned about z from -y")
    p.add_argument("--elevation", type=float, default=20.0, help="deg, camera raised above the ground")
    p.add_argument("--opacity", type=float, default=0.4, help="of the blocks, 0 to 1 (default 0.4)")
    p.add_argument("--speed-range", type=float, default=None,
                   help="m/s at the top of the colour scale (default: the largest speed at that time)")
    return p.parse_args()


def nearest(times, t):
    """the sample time of the series nearest to t (the last one when t is None)"""
    if not times:
        return 0.0
    if t is None:
        return times[-1]
    return min(times, key=lambda x: abs(x - t))


def main():
    a = arguments()
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

    # a view from the front (-y), turned and raised, the scene filling the picture
    camera = view.GetActiveCamera()
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0], centre[1] - 3.0 * diagonal, centre[2])
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.Azimuth(a.azimuth)
    camera.Elevation(a.elevation)
    view.ResetCamera(False)
    pv.Render(view)
    pv.SaveScreenshot(a.png, view, ImageResolution=[width, height])
    print("%s: t = %.3f s" % (a.png, t))


if __name__ == "__main__":
    main()
