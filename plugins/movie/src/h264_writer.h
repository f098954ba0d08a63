#pragma once
// An MP4 file of H.264 video through FFmpeg's libraries (Debian's libavcodec
// with libx264, libavformat, libswscale), kept behind this header. Frames are
// 8-bit sRGB RGB; they are converted to YUV 4:2:0 with the BT.709 matrix in
// limited range, tagged as such (sRGB transfer), the common format every player
// and slide program decodes.
#include <cstdint>
#include <memory>
#include <string>

namespace darkroom::movie {

struct H264Options {
    double frameRate = 24;         // frames per second, any positive value (29.97 is kept as 2997/100)
    int crf = 18;                  // x264 constant rate factor: 0 best .. 51 worst; 18 looks lossless
    std::string preset = "medium"; // x264 speed/size trade-off, ultrafast .. veryslow
};

class H264Writer {
public:
    // Opens `url` for writing: a "file:" URL (movie_output.h's fileUrl; the
    // caller writes to a temporary name and renames). Errors name `shownPath`,
    // the file the user asked for. Width and height must be even and
    // positive. Throws darkroom::Error naming the file and FFmpeg's reason, or
    // saying that this FFmpeg has no H.264 encoder; so do addFrame and finish
    // when a write fails (a full disk), after which the writer is only to be
    // destroyed.
    H264Writer(const std::string& url, const std::string& shownPath, int width, int height,
               const H264Options& options);
    ~H264Writer();
    H264Writer(const H264Writer&) = delete;
    H264Writer& operator=(const H264Writer&) = delete;

    // One frame: width x height RGB triplets, `stride` bytes per row.
    void addFrame(const std::uint8_t* rgb, std::size_t stride);
    // Flushes the encoder and writes the MP4 index (moved to the front of the
    // file, "faststart", so players can start before the whole file is read).
    void finish();
    int frames() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace darkroom::movie
