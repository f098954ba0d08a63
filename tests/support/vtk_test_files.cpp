#include "vtk_test_files.h"

#include "test_support.h"

#include <cmath>
#include <sstream>

namespace darkroom::test {

namespace {

void cellBlock(std::ostringstream& s, const char* tag, const std::vector<std::vector<std::uint32_t>>& cells) {
    if (cells.empty()) return;
    s << "<" << tag << "><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">";
    for (const auto& c : cells)
        for (auto i : c) s << i << " ";
    s << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">";
    std::size_t end = 0;
    for (const auto& c : cells) s << (end += c.size()) << " ";
    s << "</DataArray></" << tag << ">\n";
}

void arrays(std::ostringstream& s, const char* tag, const std::vector<std::pair<std::string, std::vector<float>>>& a) {
    if (a.empty()) return;
    s << "<" << tag << ">";
    for (const auto& [name, values] : a) {
        s << "<DataArray type=\"Float32\" Name=\"" << name << "\" format=\"ascii\">";
        for (float v : values) s << v << " ";
        s << "</DataArray>";
    }
    s << "</" << tag << ">\n";
}

}  // namespace

void writeVtp(const std::string& path, const VtpPiece& p) {
    std::ostringstream s;
    s.precision(9);
    s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << p.points.size() / 3 << "\" NumberOfVerts=\"" << p.verts.size()
      << "\" NumberOfLines=\"" << p.lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << p.polys.size()
      << "\">\n<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">";
    for (float v : p.points) s << v << " ";
    s << "</DataArray></Points>\n";
    cellBlock(s, "Verts", p.verts);
    cellBlock(s, "Lines", p.lines);
    cellBlock(s, "Polys", p.polys);
    arrays(s, "PointData", p.pointData);
    arrays(s, "CellData", p.cellData);
    s << "</Piece>\n</PolyData>\n</VTKFile>\n";
    writeText(path, s.str());
}

std::string writePvtp(const std::string& folder, const std::string& name, const std::vector<VtpPiece>& pieces) {
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "<PPolyData GhostLevel=\"0\">\n<PPoints><PDataArray type=\"Float32\" NumberOfComponents=\"3\"/></PPoints>\n";
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const std::string piece = name + "_" + std::to_string(k) + ".vtp";
        writeVtp(folder + "/" + piece, pieces[k]);
        s << "<Piece Source=\"" << piece << "\"/>\n";
    }
    s << "</PPolyData>\n</VTKFile>\n";
    const std::string path = folder + "/" + name + ".pvtp";
    writeText(path, s.str());
    return path;
}

std::vector<VtpPiece> heightFieldPieces(int nx, int ny, int pieceCount) {
    auto height = [](float x, float y) { return 0.3f * std::sin(3.0f * x) * std::cos(2.0f * y); };
    std::vector<VtpPiece> out;
    for (int k = 0; k < pieceCount; ++k) {
        const int r0 = (ny - 1) * k / pieceCount, r1 = (ny - 1) * (k + 1) / pieceCount;
        VtpPiece p;
        std::vector<float> h;
        for (int r = r0; r <= r1; ++r)
            for (int c = 0; c < nx; ++c) {
                const float x = -1.0f + 2.0f * float(c) / float(nx - 1), y = -1.0f + 2.0f * float(r) / float(ny - 1);
                p.points.insert(p.points.end(), {x, y, height(x, y)});
                h.push_back(height(x, y));
            }
        auto at = [nx](int row, int c) { return std::uint32_t(row * nx + c); };
        if (k == pieceCount - 1 && pieceCount > 1) p.verts = {{at(0, 0)}, {at(r1 - r0, nx - 1)}};
        if (k > 0) {
            std::vector<std::uint32_t> line;
            for (int c = 0; c < nx; ++c) line.push_back(at(0, c));
            p.lines.push_back(line);
        }
        for (int r = 0; r < r1 - r0; ++r)
            for (int c = 0; c + 1 < nx; ++c) p.polys.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)});
        p.pointData = {{"height", h}};
        const std::size_t cells = p.verts.size() + p.lines.size() + p.polys.size();
        p.cellData = {{"band", std::vector<float>(cells, float(k))}};
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace darkroom::test
