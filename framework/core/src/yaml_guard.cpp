#include <darkroom/core/yaml_guard.h>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace darkroom::yamlguard {

namespace {

// Counts what a walk with aliases expanded would visit, without building or
// walking anything: an anchor's expanded size is known when its node ends,
// and an alias adds that size again.
class Checker final : public YAML::EventHandler {
public:
    void OnDocumentStart(const YAML::Mark& mark) override {
        if (++documents_ > 1)
            throw YAML::ParserException(mark, "a second YAML document ('---'); the file must hold exactly one");
    }
    void OnDocumentEnd() override {}

    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        node(mark, "");
        if (anchor) names_[anchor] = pendingName_;
        if (anchor) sizes_[anchor] = {1, 0, true, "", pendingName_, true};
    }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
        node(mark, value, true);
        if (anchor) names_[anchor] = pendingName_;
        if (anchor) sizes_[anchor] = {1, value.size(), true, value, pendingName_, true};
        literalBytes_ += value.size();
        bytes_ += value.size();
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        auto it = sizes_.find(anchor);
        if (it == sizes_.end() || !it->second.closed)
            throw YAML::ParserException(mark, "alias *" + names_[anchor] +
                                                  " refers to a node it is part of (a recursive alias)");
        const Size& s = it->second;
        node(mark, s.text, s.scalar);
        --literalNodes_;  // node() counted the alias itself; count what it stands for instead
        --nodes_;
        nodes_ += s.nodes;
        bytes_ += s.bytes;
        if (nodes_ - literalNodes_ > kAliasNodeBudget || bytes_ - literalBytes_ > kAliasByteBudget)
            throw YAML::ParserException(
                mark, "aliases expand to more than " + std::to_string(kAliasNodeBudget) + " nodes or " +
                          std::to_string(kAliasByteBudget >> 20) + " MiB beyond the text (an alias bomb?); write "
                          "the values out instead");
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override {
        node(mark, "");
        open(false, anchor);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override {
        node(mark, "");
        open(true, anchor);
    }
    void OnMapEnd() override { close(); }
    void OnAnchor(const YAML::Mark&, const std::string& name) override { pendingName_ = name; }

private:
    struct Size {
        std::uint64_t nodes = 0, bytes = 0;
        bool closed = false;
        std::string text;  // scalars: the value, for duplicate keys written as aliases
        std::string name;
        bool scalar = false;
    };
    struct Frame {
        bool map = false;
        bool expectKey = true;
        YAML::anchor_t anchor = 0;
        std::uint64_t nodesAtStart = 0, bytesAtStart = 0;
        std::map<std::string, int> keys;  // scalar key -> 1-based line
    };

    // One node begins (a scalar, null, alias or collection) inside the top frame.
    void node(const YAML::Mark& mark, const std::string& scalar, bool isScalar = false) {
        ++nodes_;
        ++literalNodes_;
        if (frames_.empty()) return;
        Frame& f = frames_.back();
        if (!f.map) return;
        const bool key = f.expectKey;
        f.expectKey = !f.expectKey;
        if (!key || !isScalar) return;
        const auto [it, inserted] = f.keys.emplace(scalar, mark.line + 1);
        if (!inserted)
            throw YAML::ParserException(mark, "duplicate key '" + scalar + "' (first at line " +
                                                  std::to_string(it->second) + "); a key may appear once in a map");
    }
    void open(bool map, YAML::anchor_t anchor) {
        Frame f;
        f.map = map;
        f.anchor = anchor;
        f.nodesAtStart = nodes_ - 1;  // the collection itself
        f.bytesAtStart = bytes_;
        if (anchor) {
            names_[anchor] = pendingName_;
            sizes_[anchor] = {0, 0, false, "", pendingName_, false};
        }
        frames_.push_back(std::move(f));
    }
    void close() {
        if (frames_.empty()) return;
        const Frame& f = frames_.back();
        if (f.anchor) {
            Size& s = sizes_[f.anchor];
            s.nodes = nodes_ - f.nodesAtStart;
            s.bytes = bytes_ - f.bytesAtStart;
            s.closed = true;
        }
        frames_.pop_back();
    }

    int documents_ = 0;
    std::uint64_t nodes_ = 0, bytes_ = 0;                // with aliases expanded
    std::uint64_t literalNodes_ = 0, literalBytes_ = 0;  // as written
    std::vector<Frame> frames_;
    std::map<YAML::anchor_t, Size> sizes_;
    std::map<YAML::anchor_t, std::string> names_;
    std::string pendingName_;

};

}  // namespace

YAML::Node load(const std::string& text) {
    {
        std::istringstream in(text);
        YAML::Parser parser(in);
        Checker checker;
        while (parser.HandleNextDocument(checker)) {
        }
    }
    return YAML::Load(text);
}

}  // namespace darkroom::yamlguard
