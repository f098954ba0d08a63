#include <darkroom/data/formats/base64.h>

namespace darkroom::mesh {
namespace {

int sextet(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

bool blank(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

bool Base64Stream::quantum(std::string& error) {
    char q[4];
    int n = 0;
    while (n < 4 && pos_ < text_.size()) {
        const char c = text_[pos_++];
        if (blank(c)) continue;
        if (c != '=' && sextet(c) < 0) {
            error = "corrupt base64: unexpected character '" + std::string(1, c) + "' at character " + std::to_string(pos_ - 1);
            return false;
        }
        q[n++] = c;
    }
    if (n == 0) {
        error = "base64 data ends early (truncated)";
        return false;
    }
    if (n < 4 || q[0] == '=' || q[1] == '=' || (q[2] == '=' && q[3] != '=')) {
        error = "corrupt base64: malformed group near character " + std::to_string(pos_);
        return false;
    }
    const unsigned v = unsigned(sextet(q[0])) << 18 | unsigned(sextet(q[1])) << 12 |
                       unsigned(q[2] == '=' ? 0 : sextet(q[2])) << 6 | unsigned(q[3] == '=' ? 0 : sextet(q[3]));
    pending_.push_back(char(v >> 16));
    if (q[2] != '=') pending_.push_back(char(v >> 8 & 0xff));
    if (q[3] != '=') pending_.push_back(char(v & 0xff));
    return true;
}

bool Base64Stream::read(std::size_t n, std::string& out, std::string& error) {
    // Refuse impossible sizes before allocating for them.
    if (n > pending_.size() + (text_.size() - pos_) / 4 * 3 + 3) {
        error = "base64 data ends early (truncated): " + std::to_string(n) + " bytes expected";
        return false;
    }
    while (pending_.size() < n)
        if (!quantum(error)) return false;
    out.append(pending_, 0, n);
    pending_.erase(0, n);
    return true;
}

}  // namespace darkroom::mesh
