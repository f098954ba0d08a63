#include "h264_writer.h"

#include <darkroom/error.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <string>

namespace darkroom::movie {

namespace {

std::string averror(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

}  // namespace

struct H264Writer::Impl {
    std::string path;  // as shown in errors
    std::string url;   // as opened: "file:" and the absolute path
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scale = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    bool finished = false;
    int width = 0, height = 0;
    std::int64_t next = 0;

    void check(int code, const char* what) const {
        if (code < 0) throw Error("movie " + path + ": " + what + ": " + averror(code));
    }

    // The muxer buffers its writes and reports a failed one (a full disk, a
    // file size limit) only through the I/O context's sticky error.
    void checkWrites(const char* what) const {
        if (format && format->pb && format->pb->error < 0) check(format->pb->error, what);
    }

    // Moves every packet the encoder has ready into the file.
    void drain() {
        for (;;) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "encoding a frame");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            const int w = av_interleaved_write_frame(format, packet);
            av_packet_unref(packet);
            check(w, "writing a frame");
            checkWrites("writing a frame");
        }
    }

    // A writer destroyed before finish() succeeded was abandoned: its file is
    // incomplete and the caller removes it. The trailer is never written here
    // (after a failed av_write_trailer a second call crashed, issue 26).
    ~Impl() {
        if (format && format->pb) avio_closep(&format->pb);
        avformat_free_context(format);
        avcodec_free_context(&codec);
        sws_freeContext(scale);
        av_frame_free(&frame);
        av_packet_free(&packet);
    }
};

H264Writer::H264Writer(const std::string& url, const std::string& shownPath, int width, int height,
                       const H264Options& options)
    : impl_(std::make_unique<Impl>()) {
    Impl& d = *impl_;
    d.path = shownPath;
    d.url = url;
    const std::string& path = shownPath;
    d.width = width;
    d.height = height;
    if (width <= 0 || height <= 0 || width % 2 || height % 2)
        throw Error("movie " + path + ": frames of " + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels; H.264 4:2:0 needs an even, positive width and height");
    // x264 and the muxer report their statistics on stderr at the default
    // level; a node speaks through its errors and warnings only.
    av_log_set_level(AV_LOG_ERROR);
    const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
    if (!encoder) encoder = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!encoder)
        throw Error("this FFmpeg has no H.264 encoder (libx264); Debian's libavcodec59 includes it "
                    "(apt-get install libavcodec59)");
    d.check(avformat_alloc_output_context2(&d.format, nullptr, "mp4", url.c_str()), "preparing the MP4 container");
    d.stream = avformat_new_stream(d.format, nullptr);
    if (!d.stream) throw Error("movie " + path + ": cannot add a video stream");
    d.codec = avcodec_alloc_context3(encoder);
    if (!d.codec) throw Error("movie " + path + ": cannot allocate the encoder");
    const AVRational rate = av_d2q(options.frameRate, 100000);
    if (rate.num <= 0 || rate.den <= 0)
        throw Error("movie " + path + ": frame rate " + std::to_string(options.frameRate) + " is not usable");
    d.codec->width = width;
    d.codec->height = height;
    d.codec->framerate = rate;
    d.codec->time_base = av_inv_q(rate);
    d.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    d.codec->gop_size = std::max(1, int(options.frameRate * 2 + 0.5));  // a keyframe every 2 s for seeking
    d.codec->colorspace = AVCOL_SPC_BT709;
    d.codec->color_primaries = AVCOL_PRI_BT709;
    d.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
    d.codec->color_range = AVCOL_RANGE_MPEG;
    if (d.format->oformat->flags & AVFMT_GLOBALHEADER) d.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (std::string(encoder->name) == "libx264") {
        d.check(av_opt_set(d.codec->priv_data, "preset", options.preset.c_str(), 0), "setting the x264 preset");
        d.check(av_opt_set(d.codec->priv_data, "crf", std::to_string(options.crf).c_str(), 0), "setting the CRF");
    }
    d.check(avcodec_open2(d.codec, encoder, nullptr), "opening the H.264 encoder");
    d.check(avcodec_parameters_from_context(d.stream->codecpar, d.codec), "describing the stream");
    d.stream->time_base = d.codec->time_base;
    d.stream->avg_frame_rate = rate;
    d.check(avio_open(&d.format->pb, url.c_str(), AVIO_FLAG_WRITE), "opening the file");
    AVDictionary* muxer = nullptr;
    av_dict_set(&muxer, "movflags", "+faststart", 0);
    const int r = avformat_write_header(d.format, &muxer);
    av_dict_free(&muxer);
    d.check(r, "writing the MP4 header");
    d.checkWrites("writing the MP4 header");

    d.scale = sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P,
                             SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
    if (!d.scale) throw Error("movie " + path + ": no RGB to YUV 4:2:0 conversion");
    // Full-range RGB in, limited-range BT.709 YUV out.
    sws_setColorspaceDetails(d.scale, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0,
                             0, 1 << 16, 1 << 16);
    d.frame = av_frame_alloc();
    d.packet = av_packet_alloc();
    if (!d.frame || !d.packet) throw Error("movie " + path + ": out of memory");
    d.frame->format = AV_PIX_FMT_YUV420P;
    d.frame->width = width;
    d.frame->height = height;
    d.frame->colorspace = AVCOL_SPC_BT709;
    d.frame->color_range = AVCOL_RANGE_MPEG;
    d.check(av_frame_get_buffer(d.frame, 0), "allocating a frame");
}

H264Writer::~H264Writer() = default;

void H264Writer::addFrame(const std::uint8_t* rgb, std::size_t stride) {
    Impl& d = *impl_;
    d.check(av_frame_make_writable(d.frame), "preparing a frame");
    const std::uint8_t* src[1] = {rgb};
    const int srcStride[1] = {int(stride)};
    sws_scale(d.scale, src, srcStride, 0, d.height, d.frame->data, d.frame->linesize);
    d.frame->pts = d.next++;
    d.check(avcodec_send_frame(d.codec, d.frame), "encoding a frame");
    d.drain();
}

void H264Writer::finish() {
    Impl& d = *impl_;
    if (d.finished) return;
    d.check(avcodec_send_frame(d.codec, nullptr), "flushing the encoder");
    d.drain();
    // Once only, whatever it returns: the muxer's state after a failed
    // trailer does not survive a second call.
    d.finished = true;
    d.check(av_write_trailer(d.format), "writing the MP4 index");
    d.checkWrites("writing the MP4 index");
    d.check(avio_closep(&d.format->pb), "closing the file");
}

int H264Writer::frames() const { return int(impl_->next); }

}  // namespace darkroom::movie
