#pragma once
// A cursor over a whole file held in memory, shared by the text formats (PLY
// header and ASCII body, OBJ, legacy VTK) and the binary parts that follow a
// text header. It counts lines so every error can say "file:line: ...".
#include <darkroom/error.h>
#include <darkroom/export.h>

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom::mesh {

// Reads a whole regular file through darkroom::readInputFile: a FIFO, a device
// or a directory is refused (InputError naming the path and `what`) instead of
// blocking or reading without end; a missing file says "cannot open".
DARKROOM_API std::string readWholeFile(const std::string& path, const std::string& what = "file");

// Splits on blanks (spaces, tabs, \r).
DARKROOM_API std::vector<std::string_view> splitBlanks(std::string_view line);

class DARKROOM_API TextCursor {
public:
    TextCursor(std::string source, std::string_view data) : source_(std::move(source)), data_(data) {}

    const std::string& source() const { return source_; }
    int line() const { return line_; }
    std::size_t position() const { return pos_; }
    std::size_t remaining() const { return data_.size() - pos_; }
    bool atEnd() {
        skipSpace();
        return pos_ >= data_.size();
    }

    // Next blank-separated token; empty at end of file.
    std::string_view token();
    // Next token or an error saying what was expected there.
    std::string_view require(std::string_view expected);
    // Rest of the current line (without its newline); the cursor moves past it.
    std::string_view restOfLine();
    // Moves just past the next newline (binary data starts right after it).
    void skipLine() { restOfLine(); }

    double number(std::string_view expected);
    long long integer(std::string_view expected);

    // Raw bytes for binary bodies; nullptr when fewer than n remain.
    const char* take(std::size_t n);

    [[noreturn]] void fail(const std::string& what) const;

    // Saved position for look-ahead.
    struct Mark {
        std::size_t pos;
        int line;
    };
    Mark mark() const { return {pos_, line_}; }
    void reset(Mark m) {
        pos_ = m.pos;
        line_ = m.line;
    }

private:
    void skipSpace();
    std::string source_;
    std::string_view data_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

// Parses a whole token as a number; false if it is not one.
DARKROOM_API bool parseDouble(std::string_view token, double& out);
DARKROOM_API bool parseInteger(std::string_view token, long long& out);

}  // namespace darkroom::mesh
