// The video module, libecoview_video.so (video_encoder.hpp): H.264 in MP4 with FFmpeg's
// libraries. libswscale turns the RGB frames into YUV 4:2:0, libavcodec encodes them (libx264
// where present), libavformat writes the MP4.
#include "app/capture/video_encoder.hpp"

#include "app/errors.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <stdexcept>
#include <string>

namespace ecoview {
namespace {

const AVCodec* h264_encoder() {
  if (const AVCodec* x264 = avcodec_find_encoder_by_name("libx264")) return x264;
  return avcodec_find_encoder(AV_CODEC_ID_H264);
}

// Throws RuntimeFailure saying what failed and what FFmpeg said, where `result` is an error.
int check(int result, const char* doing) {
  if (result >= 0) return result;
  char reason[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(result, reason, sizeof reason);
  throw RuntimeFailure(std::string("cannot ") + doing + " (" + reason + ")");
}

template <class Pointer>
Pointer* made(Pointer* pointer, const char* what) {
  if (pointer == nullptr) throw RuntimeFailure(std::string("cannot make the video's ") + what + " (out of memory?)");
  return pointer;
}

// The codec's settings: the frame rate as a fraction, colour as the PNGs' sRGB turned to BT.709
// studio range, which is what players assume of H.264 without being told.
void set_up_codec(AVCodecContext& codec, int width, int height, double fps) {
  const AVRational rate = av_d2q(fps, 100000);
  codec.width = width;
  codec.height = height;
  codec.pix_fmt = AV_PIX_FMT_YUV420P;
  codec.framerate = rate;
  codec.time_base = av_inv_q(rate);
  codec.color_range = AVCOL_RANGE_MPEG;
  codec.colorspace = AVCOL_SPC_BT709;
  codec.color_primaries = AVCOL_PRI_BT709;
  codec.color_trc = AVCOL_TRC_IEC61966_2_1;
  // High quality for renders with fine foliage; the encoder's default preset.
  av_opt_set(codec.priv_data, "crf", "18", 0);
}

class H264Mp4File : public VideoEncoder {
 public:
  H264Mp4File(const char* file, int width, int height, double fps);
  ~H264Mp4File() override;
  H264Mp4File(const H264Mp4File&) = delete;
  H264Mp4File& operator=(const H264Mp4File&) = delete;

  void add(const Image8& rgb) override;
  void finish() override;

 private:
  AVFormatContext* format_ = nullptr;
  AVCodecContext* codec_ = nullptr;
  AVStream* stream_ = nullptr;
  SwsContext* to_yuv_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  long long frames_ = 0;

  void open_codec(const AVCodec& h264, int width, int height, double fps);
  void open_file(const char* file);
  void make_frame(int width, int height);
  void write_packets();
  void release();
};

H264Mp4File::H264Mp4File(const char* file, int width, int height, double fps) {
  if (width % 2 || height % 2) throw std::invalid_argument("H264Mp4File: 4:2:0 needs an even width and height");
  av_log_set_level(AV_LOG_ERROR);  // the encoder's statistics are not the capture's lines
  const AVCodec* h264 = h264_encoder();
  if (h264 == nullptr) throw RuntimeFailure(ecoview_why_no_h264());
  try {
    check(avformat_alloc_output_context2(&format_, nullptr, "mp4", file), "make an MP4 file");
    open_codec(*h264, width, height, fps);
    open_file(file);
    make_frame(width, height);
  } catch (...) {
    release();  // no destructor runs for an object whose constructor throws
    throw;
  }
}

H264Mp4File::~H264Mp4File() { release(); }

void H264Mp4File::release() {
  av_packet_free(&packet_);
  av_frame_free(&frame_);
  sws_freeContext(to_yuv_);
  to_yuv_ = nullptr;
  avcodec_free_context(&codec_);
  if (format_ && format_->pb) avio_closep(&format_->pb);
  avformat_free_context(format_);
  format_ = nullptr;
}

void H264Mp4File::open_codec(const AVCodec& h264, int width, int height, double fps) {
  stream_ = made(avformat_new_stream(format_, nullptr), "stream");
  codec_ = made(avcodec_alloc_context3(&h264), "encoder");
  set_up_codec(*codec_, width, height, fps);
  if (format_->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  check(avcodec_open2(codec_, &h264, nullptr), "open the H.264 encoder");
  check(avcodec_parameters_from_context(stream_->codecpar, codec_), "set up the video stream");
  stream_->time_base = codec_->time_base;
  stream_->avg_frame_rate = codec_->framerate;
}

void H264Mp4File::open_file(const char* file) {
  check(avio_open(&format_->pb, file, AVIO_FLAG_WRITE), "open the file to write");
  // The index at the front, so a player can start before it has the whole file.
  AVDictionary* muxer = nullptr;
  av_dict_set(&muxer, "movflags", "faststart", 0);
  const int header = avformat_write_header(format_, &muxer);
  av_dict_free(&muxer);
  check(header, "write the MP4 header");
}

void H264Mp4File::make_frame(int width, int height) {
  to_yuv_ = made(sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr,
                                nullptr, nullptr), "colour conversion");
  sws_setColorspaceDetails(to_yuv_, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0, 0,
                           1 << 16, 1 << 16);
  frame_ = made(av_frame_alloc(), "frame");
  frame_->format = AV_PIX_FMT_YUV420P;
  frame_->width = width;
  frame_->height = height;
  check(av_frame_get_buffer(frame_, 0), "make a frame");
  packet_ = made(av_packet_alloc(), "packet");
}

void H264Mp4File::add(const Image8& rgb) {
  if (rgb.width != codec_->width || rgb.height != codec_->height || rgb.channels != 3) {
    throw std::invalid_argument("H264Mp4File::add: a frame of another size or not RGB");
  }
  check(av_frame_make_writable(frame_), "reuse a frame");
  const std::uint8_t* rows[1] = {rgb.samples.data()};
  const int stride[1] = {3 * rgb.width};
  sws_scale(to_yuv_, rows, stride, 0, rgb.height, frame_->data, frame_->linesize);
  frame_->pts = frames_++;
  check(avcodec_send_frame(codec_, frame_), "encode a frame");
  write_packets();
}

void H264Mp4File::finish() {
  check(avcodec_send_frame(codec_, nullptr), "finish encoding");
  write_packets();
  check(av_write_trailer(format_), "write the MP4 index");
  check(avio_closep(&format_->pb), "close the file");
}

// The packets the encoder has ready, into the file.
void H264Mp4File::write_packets() {
  for (;;) {
    const int received = avcodec_receive_packet(codec_, packet_);
    if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
    check(received, "encode a frame");
    av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
    packet_->stream_index = stream_->index;
    check(av_interleaved_write_frame(format_, packet_), "write to the file");
  }
}

}  // namespace
}  // namespace ecoview

extern "C" ecoview::VideoEncoder* ecoview_open_h264_mp4(const char* file, int width, int height, double fps) {
  return new ecoview::H264Mp4File(file, width, height, fps);
}

extern "C" const char* ecoview_why_no_h264() {
  return ecoview::h264_encoder() ? nullptr : "this FFmpeg has no H.264 encoder (install libavcodec with libx264)";
}
