#include "output/vtk_writer.hpp"

#include <cassert>
#include <cstdio>

#include "output/number_format.hpp"

namespace cairn {

namespace {

/// a double with 17 significant digits (round-trips exactly)
void put(std::ostream& out, double x) {
    std::string s;
    append_exact(s, x);
    out << s;
}

void field(std::ostream& out, const VtkField& f) {
    out << "        <DataArray type=\"" << (f.integer ? "Int32" : "Float64") << "\" Name=\"" << f.name
        << "\" NumberOfComponents=\"" << f.components << "\" format=\"ascii\">\n";
    for (size_t i = 0; i < f.values.size(); ++i) {
        if (f.integer) out << (long long)f.values[i];
        else put(out, f.values[i]);
        out << ((i + 1) % size_t(f.components) == 0 ? '\n' : ' ');
    }
    out << "        </DataArray>\n";
}

}  // namespace

void write_vtu(std::ostream& out, const VtkGrid& g) {
    const int per_cell = g.cell_type == kVtkHexahedron ? 8 : 1;
    assert(g.connectivity.size() % size_t(per_cell) == 0);
    const size_t cells = g.cells();
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << g.points.size() << "\" NumberOfCells=\"" << cells << "\">\n";
    out << "      <PointData>\n";
    for (const auto& f : g.point_fields) field(out, f);
    out << "      </PointData>\n      <CellData>\n";
    for (const auto& f : g.cell_fields) field(out, f);
    out << "      </CellData>\n      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : g.points) {
        put(out, p.x()), out << ' ', put(out, p.y()), out << ' ', put(out, p.z()), out << '\n';
    }
    out << "        </DataArray>\n      </Points>\n      <Cells>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (size_t i = 0; i < g.connectivity.size(); ++i)
        out << g.connectivity[i] << ((i + 1) % size_t(per_cell) == 0 ? '\n' : ' ');
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (size_t c = 0; c < cells; ++c) out << (c + 1) * size_t(per_cell) << '\n';
    out << "        </DataArray>\n"
        << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (size_t c = 0; c < cells; ++c) out << g.cell_type << '\n';
    out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

void write_pvd(std::ostream& out, const std::vector<std::pair<double, std::string>>& steps) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const auto& [t, file] : steps) {
        out << "    <DataSet timestep=\"";
        put(out, t);
        out << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
}

}  // namespace cairn
