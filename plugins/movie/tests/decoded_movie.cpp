#include "decoded_movie.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <stdexcept>

namespace darkroom::test {

namespace {

void take(AVCodecContext* c, AVFrame* f, DecodedMovie& m, int x, int y) {
    while (avcodec_receive_frame(c, f) == 0) {
        double sum = 0;
        for (int row = 0; row < f->height; ++row)
            for (int col = 0; col < f->width; ++col) sum += f->data[0][row * f->linesize[0] + col];
        m.meanLuma.push_back(sum / (double(f->width) * f->height));
        m.lumaAt.push_back(f->data[0][y * f->linesize[0] + x]);
        av_frame_unref(f);
    }
}

}  // namespace

DecodedMovie decodeMovie(const std::string& path, int x, int y) {
    AVFormatContext* fmt = nullptr;
    if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) throw std::runtime_error("cannot open " + path);
    if (avformat_find_stream_info(fmt, nullptr) < 0) throw std::runtime_error("no stream info in " + path);
    const int s = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (s < 0) throw std::runtime_error("no video stream in " + path);
    const AVCodec* decoder = avcodec_find_decoder(fmt->streams[s]->codecpar->codec_id);
    AVCodecContext* c = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(c, fmt->streams[s]->codecpar);
    if (avcodec_open2(c, decoder, nullptr) < 0) throw std::runtime_error("cannot open the decoder");
    DecodedMovie m;
    m.container = fmt->iformat->name;
    m.codec = decoder->name;
    m.width = c->width;
    m.height = c->height;
    m.frameRate = av_q2d(fmt->streams[s]->avg_frame_rate);
    AVPacket* p = av_packet_alloc();
    AVFrame* f = av_frame_alloc();
    while (av_read_frame(fmt, p) >= 0) {
        if (p->stream_index == s && avcodec_send_packet(c, p) == 0) take(c, f, m, x, y);
        av_packet_unref(p);
    }
    avcodec_send_packet(c, nullptr);
    take(c, f, m, x, y);
    av_frame_free(&f);
    av_packet_free(&p);
    avcodec_free_context(&c);
    avformat_close_input(&fmt);
    return m;
}

}  // namespace darkroom::test
