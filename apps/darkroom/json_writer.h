#pragma once
// A tiny streaming JSON writer for --json outputs (no parsing needed here).
#include <cstdio>
#include <string>
#include <vector>

namespace darkroom::cli {

class JsonWriter {
public:
    JsonWriter& beginObject() { sep(); out_ += '{'; first_.push_back(true); return *this; }
    JsonWriter& endObject() { out_ += '}'; first_.pop_back(); return *this; }
    JsonWriter& beginArray() { sep(); out_ += '['; first_.push_back(true); return *this; }
    JsonWriter& endArray() { out_ += ']'; first_.pop_back(); return *this; }
    JsonWriter& key(const std::string& k) { sep(); quote(k); out_ += ':'; afterKey_ = true; return *this; }
    JsonWriter& value(const std::string& v) { sep(); quote(v); return *this; }
    JsonWriter& value(const char* v) { return value(std::string(v)); }
    JsonWriter& value(bool b) { sep(); out_ += b ? "true" : "false"; return *this; }
    JsonWriter& raw(const std::string& v) { sep(); out_ += v; return *this; }
    const std::string& str() const { return out_; }

private:
    void sep() {
        if (afterKey_) { afterKey_ = false; return; }
        if (!first_.empty()) {
            if (!first_.back()) out_ += ',';
            first_.back() = false;
        }
    }
    void quote(const std::string& s) {
        out_ += '"';
        for (unsigned char c : s) {
            switch (c) {
                case '"': out_ += "\\\""; break;
                case '\\': out_ += "\\\\"; break;
                case '\n': out_ += "\\n"; break;
                case '\t': out_ += "\\t"; break;
                case '\r': out_ += "\\r"; break;
                default:
                    if (c < 0x20) {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "\\u%04x", c);
                        out_ += buf;
                    } else {
                        out_ += char(c);
                    }
            }
        }
        out_ += '"';
    }
    std::string out_;
    std::vector<bool> first_;
    bool afterKey_ = false;
};

}  // namespace darkroom::cli
