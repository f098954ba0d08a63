// A series named by a ParaView collection (.pvd): the DataSets of its
// Collection, each a file at a timestep (ParaView's "PVD" format, as its
// writers save an animation).
#include "series_sources.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/xml_document.h>

#include <algorithm>
#include <filesystem>

namespace darkroom::series {

namespace {

constexpr const char* kExpected =
    "expected a ParaView collection: <VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" "
    "file=\"step_0.vtu\"/>...";

SeriesItem dataSet(const mesh::XmlElement& d, const std::string& path) {
    const std::string where = path + ":" + std::to_string(d.line) + ": ";
    const std::string* file = d.attribute("file");
    if (!file || file->empty()) throw InputError(where + "a DataSet without a 'file' attribute; " + kExpected);
    const std::string* step = d.attribute("timestep");
    double t = 0;
    if (!step) throw InputError(where + "DataSet '" + *file + "' has no 'timestep' attribute; " + kExpected);
    if (!mesh::parseDouble(*step, t) || !std::isfinite(t))
        throw InputError(where + "DataSet '" + *file + "': timestep '" + *step + "' is not a number");
    std::filesystem::path p = *file;
    if (p.is_relative()) p = std::filesystem::path(path).parent_path() / p;
    const std::string full = p.lexically_normal().string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec))
        throw InputError(where + "DataSet at timestep " + *step + " names '" + full +
                         "', which does not exist; expected a mesh or volume file (relative to the .pvd)");
    return {t, {}, full};
}

}  // namespace

ObjectSeries pvdSeries(const std::string& path) {
    const std::string text = readInputFile(path, "ParaView collection");
    mesh::VtkXmlDocument doc;
    try {
        doc = mesh::parseVtkXml(text, path);
    } catch (const Error& e) {
        throw InputError(std::string(e.what()) + "; " + kExpected);
    }
    const mesh::XmlElement& root = *doc.root;
    if (root.name != "VTKFile" || root.attributeOr("type", "") != "Collection")
        throw InputError(path + ":" + std::to_string(root.line) + ": <" + root.name + " type=\"" +
                         root.attributeOr("type", "") + "\"> is not a collection; " + kExpected);
    const mesh::XmlElement* collection = root.child("Collection");
    if (!collection) throw InputError(path + ":" + std::to_string(root.line) + ": no <Collection>; " + kExpected);
    ObjectSeries out;
    for (const auto& c : collection->children)
        if (c->name == "DataSet") out.items.push_back(dataSet(*c, path));
    if (out.items.empty())
        throw InputError(path + ":" + std::to_string(collection->line) + ": the collection lists no DataSet; " +
                         kExpected);
    std::stable_sort(out.items.begin(), out.items.end(),
                     [](const SeriesItem& a, const SeriesItem& b) { return *a.time < *b.time; });
    for (std::size_t i = 1; i < out.items.size(); ++i)
        if (*out.items[i].time == *out.items[i - 1].time)
            throw InputError(path + ": two DataSets at timestep " + CinemaValue(*out.items[i].time).str() + " ('" +
                             out.items[i - 1].file + "', '" + out.items[i].file +
                             "'); pieces of one step (the 'part' attribute) are not read: expected one file per "
                             "timestep");
    return out;
}

}  // namespace darkroom::series
