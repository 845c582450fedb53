#include "renderer/output/video_encoder.h"

#include "scene/core/diagnostics.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string>
#include <system_error>

namespace glint::video {

namespace {

struct CodecChoice {
    const char* encoder;
    AVPixelFormat pixelFormat;
    bool rgb;       // planar RGB: no matrix, full range
    bool evenSizes; // chroma subsampled
};

CodecChoice choiceFor(Codec codec) {
    switch (codec) {
    case Codec::H264: return {"libx264", AV_PIX_FMT_YUV420P, false, true};
    case Codec::ProRes: return {"prores_ks", AV_PIX_FMT_YUV422P10LE, false, true};
    case Codec::Ffv1: break;
    }
    return {"ffv1", AV_PIX_FMT_BGR0, true, false}; // FFV1 codes 8-bit RGB only packed (reversible colour transform inside)
}

const char* muxerFor(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext == ".mov" || ext == ".MOV") return "mov";
    if (ext == ".mkv" || ext == ".MKV") return "matroska";
    return "mp4";
}

std::string avError(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

std::filesystem::path temporaryNameFor(const std::filesystem::path& file) {
    return file.parent_path() / ("." + file.stem().string() + ".partial" + file.extension().string());
}

} // namespace

struct VideoEncoder::State {
    std::filesystem::path file;
    std::filesystem::path temp;
    int width = 0, height = 0, codedWidth = 0, codedHeight = 0;
    AVFormatContext* format = nullptr;
    AVCodecContext* encoder = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scaler = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::int64_t nextPts = 0;
    bool finished = false;
    std::vector<std::uint8_t> padded;

    ~State() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        sws_freeContext(scaler);
        avcodec_free_context(&encoder);
        if (format && format->pb) avio_closep(&format->pb);
        avformat_free_context(format);
        std::error_code ec;
        if (!finished && !temp.empty()) std::filesystem::remove(temp, ec);
    }

    [[noreturn]] void fail(const std::string& what, int code) const {
        throw FileError(file.string(), "video-failed", what + (code ? ": " + avError(code) : std::string()));
    }
    void check(int code, const char* what) const {
        if (code < 0) fail(what, code);
    }
    // The finished video reaches the disk before it replaces one there: after a power loss the name
    // holds the old video or the whole new one, as with images (image_files.cpp).
    void syncToDisk() const {
        const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) fail("cannot flush the video to disk", AVERROR(errno));
        const int result = ::fsync(fd);
        const int error = errno;
        ::close(fd);
        if (result != 0) fail("cannot flush the video to disk", AVERROR(error));
    }

    void openEncoder(const VideoSettings& settings, const CodecChoice& choice) {
        const AVCodec* codec = avcodec_find_encoder_by_name(choice.encoder);
        if (!codec) fail(std::string("this FFmpeg has no ") + choice.encoder + " encoder", 0);
        encoder = avcodec_alloc_context3(codec);
        stream = avformat_new_stream(format, nullptr);
        if (!encoder || !stream) fail("out of memory", 0);
        encoder->width = codedWidth;
        encoder->height = codedHeight;
        encoder->pix_fmt = choice.pixelFormat;
        encoder->time_base = AVRational{settings.fpsDenominator, settings.fpsNumerator};
        encoder->framerate = AVRational{settings.fpsNumerator, settings.fpsDenominator};
        encoder->thread_count = kEncoderThreads;
        encoder->color_primaries = AVCOL_PRI_BT709;
        encoder->color_trc = AVCOL_TRC_BT709;
        encoder->colorspace = choice.rgb ? AVCOL_SPC_RGB : AVCOL_SPC_BT709;
        encoder->color_range = choice.rgb ? AVCOL_RANGE_JPEG : AVCOL_RANGE_MPEG;
        encoder->flags |= AV_CODEC_FLAG_BITEXACT; // no version strings that change the bytes
        if (format->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        if (settings.codec == Codec::H264) av_opt_set(encoder->priv_data, "crf", std::to_string(settings.crf).c_str(), 0);
        if (settings.codec == Codec::ProRes) av_opt_set(encoder->priv_data, "profile", "hq", 0);
        check(avcodec_open2(encoder, codec, nullptr), "cannot open the encoder");
        check(avcodec_parameters_from_context(stream->codecpar, encoder), "cannot describe the stream");
        stream->time_base = encoder->time_base;
        stream->avg_frame_rate = encoder->framerate;
    }

    void openScaler(const CodecChoice& choice) {
        scaler = sws_getContext(codedWidth, codedHeight, AV_PIX_FMT_RGBA, codedWidth, codedHeight, choice.pixelFormat,
                                SWS_POINT | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
        if (!scaler) fail("cannot set up the colour conversion", 0);
        if (!choice.rgb) {
            const int* srgb = sws_getCoefficients(SWS_CS_ITU709);
            check(sws_setColorspaceDetails(scaler, srgb, 1, srgb, 0, 0, 1 << 16, 1 << 16), "cannot set BT.709 conversion");
        }
        frame = av_frame_alloc();
        packet = av_packet_alloc();
        if (!frame || !packet) fail("out of memory", 0);
        frame->format = choice.pixelFormat;
        frame->width = codedWidth;
        frame->height = codedHeight;
        check(av_frame_get_buffer(frame, 0), "cannot allocate a frame");
    }

    // Sends a frame (or nullptr to flush) and writes every packet the encoder has ready.
    void send(AVFrame* f) {
        check(avcodec_send_frame(encoder, f), "cannot encode a frame");
        for (;;) {
            const int r = avcodec_receive_packet(encoder, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "cannot encode a frame");
            av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(format, packet), "cannot write the video");
        }
    }

    // Copies the image into the coded size, repeating the last column and row into the padding.
    const std::uint8_t* pad(const std::vector<std::uint8_t>& rgba) {
        if (codedWidth == width && codedHeight == height) return rgba.data();
        padded.resize(std::size_t(codedWidth) * std::size_t(codedHeight) * 4);
        for (int y = 0; y < codedHeight; ++y)
            for (int x = 0; x < codedWidth; ++x) {
                const std::size_t from = (std::size_t(std::min(y, height - 1)) * std::size_t(width) + std::size_t(std::min(x, width - 1))) * 4;
                const std::size_t to = (std::size_t(y) * std::size_t(codedWidth) + std::size_t(x)) * 4;
                std::copy_n(rgba.begin() + std::ptrdiff_t(from), 4, padded.begin() + std::ptrdiff_t(to));
            }
        return padded.data();
    }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& file, const VideoSettings& settings, int width, int height)
    : state_(std::make_unique<State>()) {
    // libav's own progress and statistics lines would drown Glint's one-line messages; its
    // errors come back through return codes, which are reported with the file name.
    av_log_set_level(AV_LOG_ERROR);
    State& s = *state_;
    s.file = file;
    s.temp = temporaryNameFor(file);
    const CodecChoice choice = choiceFor(settings.codec);
    s.width = width;
    s.height = height;
    s.codedWidth = choice.evenSizes ? (width + 1) / 2 * 2 : width;
    s.codedHeight = choice.evenSizes ? (height + 1) / 2 * 2 : height;
    s.check(avformat_alloc_output_context2(&s.format, nullptr, muxerFor(file), s.temp.c_str()), "cannot create the container");
    s.format->flags |= AVFMT_FLAG_BITEXACT;
    s.openEncoder(settings, choice);
    s.openScaler(choice);
    s.check(avio_open(&s.format->pb, s.temp.c_str(), AVIO_FLAG_WRITE), "cannot create the file");
    s.check(avformat_write_header(s.format, nullptr), "cannot write the container header");
}

VideoEncoder::~VideoEncoder() = default;

int VideoEncoder::codedWidth() const { return state_->codedWidth; }
int VideoEncoder::codedHeight() const { return state_->codedHeight; }

void VideoEncoder::addFrame(const std::vector<std::uint8_t>& rgba) {
    State& s = *state_;
    if (rgba.size() != std::size_t(s.width) * std::size_t(s.height) * 4)
        s.fail("a frame's size differs from the first frame's (" + std::to_string(s.width) + "x" + std::to_string(s.height) + ")", 0);
    s.check(av_frame_make_writable(s.frame), "cannot reuse a frame");
    const std::uint8_t* source[1] = {s.pad(rgba)};
    const int stride[1] = {s.codedWidth * 4};
    sws_scale(s.scaler, source, stride, 0, s.codedHeight, s.frame->data, s.frame->linesize);
    s.frame->pts = s.nextPts++;
    s.send(s.frame);
}

void VideoEncoder::finish() {
    State& s = *state_;
    s.send(nullptr);
    s.check(av_write_trailer(s.format), "cannot finish the container");
    s.check(avio_closep(&s.format->pb), "cannot close the file");
    s.syncToDisk();
    std::error_code ec;
    std::filesystem::rename(s.temp, s.file, ec);
    if (ec) s.fail("cannot move the finished video into place: " + ec.message(), 0);
    s.finished = true;
}

} // namespace glint::video
