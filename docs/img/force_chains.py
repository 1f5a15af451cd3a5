"""The force-chain picture of docs/output.md ("Contact snapshots"), rendered with VTK's Python as the
ParaView recipe there does it: the contact lines through a Tube filter whose radius varies with
normal_force_magnitude, coloured by it, over translucent particles. Input: a run of
examples/python/bed_stress.py's scene with [output] contacts_every and particles_every set
(contacts/contacts_000000.vtu, particles/particles_000001.vtu in the working folder).
Run without a display:  xvfb-run -a /usr/bin/python3 docs/img/force_chains.py
"""
import vtk
def reader(f):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f); r.Update(); return r
c = reader("contacts/contacts_000000.vtu")
c.GetOutput().GetCellData().SetActiveScalars("normal_force_magnitude")
geo = vtk.vtkGeometryFilter(); geo.SetInputConnection(c.GetOutputPort())
c2p = vtk.vtkCellDataToPointData(); c2p.SetInputConnection(geo.GetOutputPort())
tube = vtk.vtkTubeFilter(); tube.SetInputConnection(c2p.GetOutputPort())
tube.SetVaryRadiusToVaryRadiusByScalar(); tube.SetRadius(0.00006); tube.SetRadiusFactor(6); tube.SetNumberOfSides(10)
rng = c.GetOutput().GetCellData().GetArray("normal_force_magnitude").GetRange()
m = vtk.vtkPolyDataMapper(); m.SetInputConnection(tube.GetOutputPort()); m.SetScalarRange(0, rng[1])
lut = vtk.vtkLookupTable(); lut.SetHueRange(0.66, 0.0); lut.Build(); m.SetLookupTable(lut)
a = vtk.vtkActor(); a.SetMapper(m)
p = reader("particles/particles_000001.vtu")
p.GetOutput().GetPointData().SetActiveScalars("radius")
sph = vtk.vtkSphereSource(); sph.SetRadius(1.0); sph.SetThetaResolution(12); sph.SetPhiResolution(12)
g = vtk.vtkGlyph3D(); g.SetInputConnection(p.GetOutputPort()); g.SetSourceConnection(sph.GetOutputPort())
g.SetScaleModeToScaleByScalar(); g.SetScaleFactor(1.0)
pm = vtk.vtkPolyDataMapper(); pm.SetInputConnection(g.GetOutputPort()); pm.ScalarVisibilityOff()
pa = vtk.vtkActor(); pa.SetMapper(pm); pa.GetProperty().SetOpacity(0.12); pa.GetProperty().SetColor(0.7, 0.7, 0.7)
bar = vtk.vtkScalarBarActor(); bar.SetLookupTable(m.GetLookupTable()); bar.SetTitle("|F_n| [N]"); bar.SetNumberOfLabels(4)
bar.SetWidth(0.08); bar.SetHeight(0.6)
r = vtk.vtkRenderer(); r.AddActor(a); r.AddActor(pa); r.AddActor2D(bar); r.SetBackground(1, 1, 1)
bar.GetTitleTextProperty().SetColor(0, 0, 0); bar.GetLabelTextProperty().SetColor(0, 0, 0)
w = vtk.vtkRenderWindow(); w.SetOffScreenRendering(1); w.AddRenderer(r); w.SetSize(900, 900)
cam = r.GetActiveCamera(); cam.SetPosition(0.09, -0.07, 0.045); cam.SetFocalPoint(0.008, 0.008, 0.017); cam.SetViewUp(0, 0, 1)
r.ResetCameraClippingRange(); w.Render()
wi = vtk.vtkWindowToImageFilter(); wi.SetInput(w); wi.Update()
pw = vtk.vtkPNGWriter(); pw.SetFileName("force_chains.png"); pw.SetInputConnection(wi.GetOutputPort()); pw.Write()
print("range", rng)
