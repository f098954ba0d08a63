#include <darkroom/data/formats/xml_document.h>

#include <darkroom/error.h>

#include <expat.h>

#include <limits>

namespace darkroom::mesh {
namespace {

// VTK files nest six or seven elements deep. The tree and every walk over it
// (findAppended, the destructors of XmlElement) recurse once per level, so a
// forged file of a few hundred thousand nested elements would overflow the
// stack: nesting beyond this is refused while parsing.
constexpr std::size_t kMaxDepth = 256;

struct Builder {
    XML_Parser parser = nullptr;
    std::unique_ptr<XmlElement> root;
    std::vector<XmlElement*> stack;
    bool multipleRoots = false;
    std::string tooDeep;  // the error, once nesting went beyond kMaxDepth
};

void XMLCALL onStart(void* user, const XML_Char* name, const XML_Char** atts) {
    auto* b = static_cast<Builder*>(user);
    if (b->stack.size() >= kMaxDepth) {
        if (b->tooDeep.empty())
            b->tooDeep = ":" + std::to_string(XML_GetCurrentLineNumber(b->parser)) + ": <" + std::string(name) +
                         "> at byte offset " + std::to_string(XML_GetCurrentByteIndex(b->parser)) +
                         " is nested " + std::to_string(b->stack.size() + 1) + " elements deep; expected at most " +
                         std::to_string(kMaxDepth) + " (a VTK file nests about 7)";
        XML_StopParser(b->parser, XML_FALSE);
        return;
    }
    auto e = std::make_unique<XmlElement>();
    e->name = name;
    e->line = int(XML_GetCurrentLineNumber(b->parser));
    for (int i = 0; atts[i]; i += 2) e->attributes.emplace_back(atts[i], atts[i + 1]);
    XmlElement* raw = e.get();
    if (b->stack.empty()) {
        if (b->root) b->multipleRoots = true;
        b->root = std::move(e);
    } else {
        b->stack.back()->children.push_back(std::move(e));
    }
    b->stack.push_back(raw);
}

void XMLCALL onEnd(void* user, const XML_Char*) {
    auto* b = static_cast<Builder*>(user);
    if (!b->stack.empty()) b->stack.pop_back();
}

void XMLCALL onText(void* user, const XML_Char* s, int len) {
    auto* b = static_cast<Builder*>(user);
    if (!b->stack.empty()) b->stack.back()->text.append(s, std::size_t(len));
}

const XmlElement* findAppended(const XmlElement* e) {
    if (!e) return nullptr;
    if (e->name == "AppendedData") return e;
    for (const auto& c : e->children)
        if (const XmlElement* f = findAppended(c.get())) return f;
    return nullptr;
}

}  // namespace

VtkXmlDocument parseVtkXml(std::string_view data, const std::string& source) {
    // Markup ends where the appended block's '_' marker starts the raw bytes;
    // expat sees the text up to the end of the <AppendedData ...> start tag.
    std::string_view markup = data;
    std::string_view appended;
    bool final = true;
    const std::size_t tag = data.find("<AppendedData");
    if (tag != std::string_view::npos) {
        const std::size_t gt = data.find('>', tag);
        const std::size_t mark = gt == std::string_view::npos ? gt : data.find('_', gt);
        if (mark == std::string_view::npos) throw Error(source + ": <AppendedData> without its '_' marker");
        markup = data.substr(0, gt + 1);
        appended = data.substr(mark + 1);
        final = false;
    }
    if (markup.size() > std::size_t(std::numeric_limits<int>::max()))
        throw InputError(source + ": " + std::to_string(markup.size()) +
                         " bytes of XML markup; expected at most 2 GiB (put large arrays in <AppendedData>)");
    Builder b;
    b.parser = XML_ParserCreate(nullptr);
    if (!b.parser) throw Error(source + ": cannot create an XML parser");
    XML_SetUserData(b.parser, &b);
    XML_SetElementHandler(b.parser, onStart, onEnd);
    XML_SetCharacterDataHandler(b.parser, onText);
    const auto status = XML_Parse(b.parser, markup.data(), int(markup.size()), final ? 1 : 0);
    if (!b.tooDeep.empty()) {
        XML_ParserFree(b.parser);
        throw InputError(source + b.tooDeep);
    }
    if (status != XML_STATUS_OK) {
        const std::string msg = source + ":" + std::to_string(XML_GetCurrentLineNumber(b.parser)) + ":" +
                                std::to_string(XML_GetCurrentColumnNumber(b.parser) + 1) +
                                ": malformed XML: " + XML_ErrorString(XML_GetErrorCode(b.parser));
        XML_ParserFree(b.parser);
        throw Error(msg);
    }
    XML_ParserFree(b.parser);
    if (!b.root) throw Error(source + ": no XML element found (expected <VTKFile>)");
    VtkXmlDocument doc;
    doc.root = std::move(b.root);
    doc.appendedElement = findAppended(doc.root.get());
    doc.appended = appended;
    if (!final && !doc.appendedElement) throw Error(source + ": <AppendedData> found outside the XML markup");
    return doc;
}

}  // namespace darkroom::mesh
