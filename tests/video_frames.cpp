#include "video_frames.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace ecoview::test {
namespace {

struct Decoder {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* to_rgb = nullptr;
  ~Decoder() {
    sws_freeContext(to_rgb);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }
};

// The frames the decoder has ready, as RGB.
void take_frames(Decoder& d, VideoFrames& video) {
  while (avcodec_receive_frame(d.codec, d.frame) >= 0) {
    d.to_rgb = sws_getCachedContext(d.to_rgb, d.frame->width, d.frame->height, static_cast<AVPixelFormat>(d.frame->format),
                                    d.frame->width, d.frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC, nullptr, nullptr, nullptr);
    std::vector<unsigned char> rgb(static_cast<std::size_t>(d.frame->width) * static_cast<std::size_t>(d.frame->height) * 3);
    std::uint8_t* rows[1] = {rgb.data()};
    const int stride[1] = {3 * d.frame->width};
    sws_scale(d.to_rgb, d.frame->data, d.frame->linesize, 0, d.frame->height, rows, stride);
    video.rgb.push_back(std::move(rgb));
  }
}

}  // namespace

VideoFrames read_video_frames(const std::filesystem::path& file) {
  VideoFrames video;
  Decoder d;
  if (avformat_open_input(&d.format, file.c_str(), nullptr, nullptr) < 0) return video.error = "cannot open", video;
  if (avformat_find_stream_info(d.format, nullptr) < 0) return video.error = "no stream info", video;
  const AVCodec* decoder = nullptr;
  const int stream = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (stream < 0 || decoder == nullptr) return video.error = "no video stream", video;
  const AVStream& s = *d.format->streams[stream];
  video.codec = avcodec_get_name(s.codecpar->codec_id);
  video.width = s.codecpar->width;
  video.height = s.codecpar->height;
  video.rate_num = s.avg_frame_rate.num;
  video.rate_den = s.avg_frame_rate.den;
  d.codec = avcodec_alloc_context3(decoder);
  d.frame = av_frame_alloc();
  d.packet = av_packet_alloc();
  if (avcodec_parameters_to_context(d.codec, s.codecpar) < 0 || avcodec_open2(d.codec, decoder, nullptr) < 0) {
    return video.error = "cannot open the decoder", video;
  }
  while (av_read_frame(d.format, d.packet) >= 0) {
    if (d.packet->stream_index == stream) avcodec_send_packet(d.codec, d.packet);
    av_packet_unref(d.packet);
    take_frames(d, video);
  }
  avcodec_send_packet(d.codec, nullptr);  // the frames the decoder holds back
  take_frames(d, video);
  return video;
}

}  // namespace ecoview::test
