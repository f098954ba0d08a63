#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/input_file.h>

#include <filesystem>

namespace darkroom::mesh {

std::string readWholeFile(const std::string& path, const std::string& what) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path + ": cannot open file for reading (no such file)");
    return readInputFile(path, what);
}

std::vector<std::string_view> splitBlanks(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t b = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > b) out.push_back(line.substr(b, i - b));
    }
    return out;
}

bool parseDouble(std::string_view t, double& out) {
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
    if (t.empty()) return false;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
    return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

bool parseInteger(std::string_view t, long long& out) {
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    if (t.empty()) return false;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
    return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

void TextCursor::skipSpace() {
    while (pos_ < data_.size()) {
        const char c = data_[pos_];
        if (c == '\n')
            ++line_;
        else if (c != ' ' && c != '\t' && c != '\r' && c != '\f' && c != '\v')
            break;
        ++pos_;
    }
}

std::string_view TextCursor::token() {
    skipSpace();
    const std::size_t b = pos_;
    while (pos_ < data_.size()) {
        const char c = data_[pos_];
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v') break;
        ++pos_;
    }
    return data_.substr(b, pos_ - b);
}

std::string_view TextCursor::require(std::string_view expected) {
    const std::string_view t = token();
    if (t.empty()) fail("unexpected end of file, expected " + std::string(expected));
    return t;
}

std::string_view TextCursor::restOfLine() {
    const std::size_t b = pos_;
    while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
    std::string_view l = data_.substr(b, pos_ - b);
    if (pos_ < data_.size()) {
        ++pos_;
        ++line_;
    }
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return l;
}

double TextCursor::number(std::string_view expected) {
    const std::string_view t = require(expected);
    double v = 0;
    if (!parseDouble(t, v)) fail("expected " + std::string(expected) + ", got '" + std::string(t.substr(0, 40)) + "'");
    return v;
}

long long TextCursor::integer(std::string_view expected) {
    const std::string_view t = require(expected);
    long long v = 0;
    if (!parseInteger(t, v)) fail("expected " + std::string(expected) + ", got '" + std::string(t.substr(0, 40)) + "'");
    return v;
}

const char* TextCursor::take(std::size_t n) {
    if (data_.size() - pos_ < n) return nullptr;
    const char* p = data_.data() + pos_;
    pos_ += n;
    return p;
}

void TextCursor::fail(const std::string& what) const {
    throw Error(source_ + ":" + std::to_string(line_) + ": " + what);
}

}  // namespace darkroom::mesh
