#!/usr/bin/python3
"""Independent reader for mpdem's ParaView output, used by tests/io/test_vtu_writer.cpp.

    read_vtu.py FILE.vtu   reads with meshio and prints, for the points, every cell block and
                           every point/cell/field data array, a header line
                               <kind> <name> <tuples> <components>
                           followed by one line per tuple; floats are printed with repr()
                           (shortest exact round trip), integers as integers.
    read_vtu.py FILE.pvd   parses with xml.etree and prints "dataset <timestep> <file>" per DataSet.
    read_vtu.py --vtk FILE.vt?  reads with VTK's own Python reader (vtkXMLGenericDataObjectReader)
                           and prints the points and the point/cell/field data arrays as above
                           (the same lines meshio's reading gives, in the order of the names).
    read_vtu.py --xml FILE.vtu
                           structure only, with xml.etree (meshio 5 cannot read a grid with zero
                           cells): "piece <points> <cells>" per Piece, then "array <name> <count>"
                           per DataArray, count = number of whitespace-separated values.

Run with /usr/bin/python3 (the interpreter that has meshio and numpy).
"""
import sys
import xml.etree.ElementTree as ET

import numpy as np


def fmt(x):
    if isinstance(x, (np.integer, int)):
        return str(int(x))
    return repr(float(x))


def dump(kind, name, array):
    a = np.asarray(array)
    if a.ndim == 1:
        a = a.reshape(-1, 1)
    a = a.reshape(a.shape[0], -1)
    print(f"{kind} {name} {a.shape[0]} {a.shape[1]}")
    for row in a:
        print(" ".join(fmt(x) for x in row))


def read_vtu(path):
    import meshio

    mesh = meshio.read(path)
    dump("points", "Points", mesh.points)
    for block in mesh.cells:
        dump("cells", block.type, block.data)
    for name, array in sorted((mesh.point_data or {}).items()):
        dump("point_data", name, array)
    for name, blocks in sorted((mesh.cell_data or {}).items()):
        # one entry per cell block; the writers use a single cell type per file
        dump("cell_data", name, np.concatenate([np.asarray(b) for b in blocks]))
    for name, array in sorted((mesh.field_data or {}).items()):
        dump("field_data", name, array)


def read_vtk(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLGenericDataObjectReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data is None or reader.GetErrorCode() != 0:
        sys.exit(f"{path}: VTK could not read it")
    points = data.GetPoints() if hasattr(data, "GetPoints") else None  # ImageData has none
    if points is not None:
        dump("points", "Points", vtk_to_numpy(points.GetData()))
    for kind, fields in (("point_data", data.GetPointData()), ("cell_data", data.GetCellData()),
                         ("field_data", data.GetFieldData())):
        names = sorted(fields.GetArrayName(k) for k in range(fields.GetNumberOfArrays()))
        for name in names:
            dump(kind, name, vtk_to_numpy(fields.GetAbstractArray(name)))


def read_pvd(path):
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.attrib.get("type") != "Collection":
        sys.exit(f"{path}: not a VTK Collection")
    for ds in root.iter("DataSet"):
        print(f"dataset {ds.attrib['timestep']} {ds.attrib['file']}")


def read_xml_structure(path):
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.attrib.get("type") != "UnstructuredGrid":
        sys.exit(f"{path}: not a VTK UnstructuredGrid")
    for piece in root.iter("Piece"):
        print(f"piece {piece.attrib['NumberOfPoints']} {piece.attrib['NumberOfCells']}")
    for da in root.iter("DataArray"):
        print(f"array {da.attrib.get('Name', '?')} {len((da.text or '').split())}")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--xml":
        read_xml_structure(sys.argv[2])
        return
    if len(sys.argv) == 3 and sys.argv[1] == "--vtk":
        read_vtk(sys.argv[2])
        return
    if len(sys.argv) != 2:
        sys.exit("usage: read_vtu.py [--xml] FILE.vtu | FILE.pvd")
    path = sys.argv[1]
    if path.endswith(".pvd"):
        read_pvd(path)
    else:
        read_vtu(path)


if __name__ == "__main__":
    main()
