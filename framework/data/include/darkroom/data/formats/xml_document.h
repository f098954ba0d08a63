#pragma once
// A small element tree for VTK XML files, parsed with expat. Kept out of the
// public headers. VTK files may end in raw binary "appended" data that is not
// XML; parseVtkXml() parses only the markup before it and reports where the
// appended bytes start.
#include <darkroom/export.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom::mesh {

struct XmlElement {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;
    std::vector<std::unique_ptr<XmlElement>> children;
    std::string text;  // character data directly inside this element
    int line = 0;

    // nullptr when absent.
    const std::string* attribute(std::string_view key) const {
        for (const auto& [k, v] : attributes)
            if (k == key) return &v;
        return nullptr;
    }
    std::string attributeOr(std::string_view key, std::string fallback) const {
        const std::string* v = attribute(key);
        return v ? *v : std::move(fallback);
    }
    const XmlElement* child(std::string_view n) const {
        for (const auto& c : children)
            if (c->name == n) return c.get();
        return nullptr;
    }
};

struct VtkXmlDocument {
    std::unique_ptr<XmlElement> root;
    const XmlElement* appendedElement = nullptr;  // <AppendedData>, if any
    std::string_view appended;                    // the bytes after its '_' marker
};

// Throws darkroom::Error("source:line: ...") on malformed markup.
DARKROOM_API VtkXmlDocument parseVtkXml(std::string_view data, const std::string& source);

}  // namespace darkroom::mesh
