#pragma once
/// A small writer of the documented VTK XML formats read by ParaView (docs/visualisation.md):
/// unstructured grids (.vtu) of hexahedra or vertices with point and cell fields, and the
/// collection file (.pvd) that makes a time series of them. Data are inline ascii with 17
/// significant digits, so a file read back gives the same doubles.

#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/types.hpp"

namespace cairn {

/// VTK cell type numbers (vtkCellType.h)
constexpr int kVtkVertex = 1;
constexpr int kVtkHexahedron = 12;

/// One named field: `components` numbers per point or per cell, stored point after point.
struct VtkField {
    std::string name;            ///< field name as ParaView shows it
    int components = 1;          ///< 1 (scalar) or 3 (vector)
    std::vector<double> values;  ///< size = count × components, in the field's unit
    bool integer = false;        ///< written as Int32 (ids), else Float64
};

/// An unstructured grid whose cells are all of one type.
struct VtkGrid {
    std::vector<Vec3> points;                  ///< m
    int cell_type = kVtkHexahedron;            ///< kVtkHexahedron (8 points) or kVtkVertex (1)
    std::vector<int> connectivity;             ///< point indices, 8 (hexahedron) or 1 per cell
    std::vector<VtkField> point_fields;        ///< one value set per point
    std::vector<VtkField> cell_fields;         ///< one value set per cell
    /// number of cells
    size_t cells() const { return connectivity.size() / (cell_type == kVtkHexahedron ? 8 : 1); }
};

/// write `grid` as a VTK XML UnstructuredGrid (.vtu)
void write_vtu(std::ostream& out, const VtkGrid& grid);

/// write a ParaView collection (.pvd) of (time in s, file name relative to the .pvd) entries
void write_pvd(std::ostream& out, const std::vector<std::pair<double, std::string>>& steps);

}  // namespace cairn
