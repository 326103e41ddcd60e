#include "io/image_io.h"

#include "io/stderr_capture.h"
#include "scene/estimator_stages.h"
#include "shaders/include/tone_map.glsl"
#include "texture/image_size.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace raylab {
namespace fs = std::filesystem;
namespace {

fs::path temporarySibling(const fs::path& path) {
    // Keep the extension: OpenImageIO picks the writer by it.
    fs::path tmp = path;
    tmp.replace_filename("." + path.stem().string() + ".tmp" + std::to_string(::getpid()) +
                         path.extension().string());
    return tmp;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// R, G, B, A, then an adaptive render's state in the order AdaptiveState::half has it, then its counts.
constexpr std::array<const char*, 9> kRgbaAndAdaptive = {"R", "G", "B", "A", "adaptive.half.R", "adaptive.half.G",
                                                         "adaptive.half.B", "adaptive.rays", "adaptive.samples"};

} // namespace

int toneMapOp(ToneMap t) {
    switch (t) {
    case ToneMap::Clamp: return glsl::TONE_MAP_CLAMP;
    case ToneMap::Reinhard: return glsl::TONE_MAP_REINHARD;
    case ToneMap::AcesFit: return glsl::TONE_MAP_ACES_FIT;
    }
    return glsl::TONE_MAP_CLAMP;
}

ImageFormat imageFormatFor(const fs::path& path) {
    const std::string ext = lower(path.extension().string());
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".png") return ImageFormat::Png;
    throw ImageIoError(path.string() + ": error: unsupported output format '" + ext +
                       "' (use .exr for linear HDR or .png for a tone-mapped image)");
}

void checkWritable(const fs::path& path) {
    imageFormatFor(path);
    const fs::path tmp = temporarySibling(path);
    {
        std::ofstream probe(tmp, std::ios::binary);
        if (!probe)
            throw ImageIoError(path.string() + ": error: cannot write: " +
                               std::error_code(errno, std::generic_category()).message());
    }
    std::error_code ec;
    fs::remove(tmp, ec);
}

std::uint8_t displayByte(float linear, const DisplayTransform& display) {
    const float v = glsl::displayValue(linear, display.exposure, toneMapOp(display.toneMap));
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void writeImage(const fs::path& path, const Image& image, const RenderMetadata& meta,
                const DisplayTransform& display, const AdaptiveState* adaptive) {
    using namespace OIIO;
    const ImageFormat format = imageFormatFor(path);
    const fs::path tmp = temporarySibling(path);
    auto out = ImageOutput::create(tmp.string());
    if (!out) throw ImageIoError(path.string() + ": error: " + OIIO::geterror());

    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    if (format != ImageFormat::Exr) adaptive = nullptr;
    if (adaptive && (adaptive->samples.size() != pixels || adaptive->half.size() != 4 * pixels))
        throw std::invalid_argument("writeImage: the adaptive state is not of the image's size");
    const int channels = format == ImageFormat::Exr ? (adaptive ? int(kRgbaAndAdaptive.size()) : 4) : 3;
    ImageSpec spec(image.width, image.height, channels,
                   format == ImageFormat::Exr ? TypeDesc::FLOAT : TypeDesc::UINT8);
    if (adaptive) {
        spec.channelnames.assign(kRgbaAndAdaptive.begin(), kRgbaAndAdaptive.end());
        spec.channelformats.assign(kRgbaAndAdaptive.size(), TypeDesc::FLOAT);
        spec.channelformats.back() = TypeDesc::UINT32;   // adaptive.samples: exact past 2^24
        spec.attribute("raylab:adaptive_gate_closed_at", int(std::min<std::uint64_t>(adaptive->gateClosedAt, 0x7fffffff)));
    }
    spec.attribute("Software", "raylab " RAYLAB_VERSION);
    spec.attribute("raylab:version", RAYLAB_VERSION);
    spec.attribute("raylab:spp", int(std::min<std::uint64_t>(meta.spp, 0x7fffffff)));
    spec.attribute("raylab:render_seconds", float(meta.renderSeconds));
    spec.attribute("raylab:seed", unsigned(meta.seed));
    spec.attribute("raylab:scene", meta.sceneFile);
    spec.attribute("raylab:sampler", meta.sampler);
    for (const auto& [name, value] : meta.stages) spec.attribute("raylab:" + name, value);
    spec.attribute("raylab:nonfinite_samples", int(std::min<std::uint64_t>(meta.nonFiniteSamples, 0x7fffffff)));
    spec.attribute("raylab:target_spp", int(std::min<std::uint64_t>(meta.targetSpp, 0x7fffffff)));
    spec.attribute("raylab:rpp", meta.rpp);
    spec.attribute("raylab:passes", int(std::min<std::uint64_t>(meta.passes, 0x7fffffff)));
    spec.attribute("raylab:tracer", meta.tracer);
    spec.attribute("raylab:settings_hash", meta.settingsHash);
    if (format == ImageFormat::Exr) spec.attribute("compression", "zip");

    bool ok = out->open(tmp.string(), spec);
    if (ok) {
        if (adaptive) {
            // The file's own formats per channel, pixel after pixel: eight floats, then the count.
            struct Native {
                float rgba[4];
                float half[4];
                std::uint32_t samples;
            };
            static_assert(sizeof(Native) == 9 * 4);
            std::vector<Native> native(pixels);
            for (std::size_t i = 0; i < pixels; ++i) {
                std::copy_n(image.rgba.begin() + std::ptrdiff_t(4 * i), 4, native[i].rgba);
                std::copy_n(adaptive->half.begin() + std::ptrdiff_t(4 * i), 4, native[i].half);
                native[i].samples = adaptive->samples[i];
            }
            ok = out->write_image(TypeDesc::UNKNOWN, native.data());
        } else if (format == ImageFormat::Exr) {
            ok = out->write_image(TypeDesc::FLOAT, image.rgba.data());
        } else {
            std::vector<std::uint8_t> bytes(size_t(image.width) * image.height * 3);
            for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i)
                for (size_t c = 0; c < 3; ++c) bytes[i * 3 + c] = displayByte(image.rgba[i * 4 + c], display);
            ok = out->write_image(TypeDesc::UINT8, bytes.data());
        }
        ok = out->close() && ok;
    }
    if (!ok) {
        const std::string err = out->geterror();
        std::error_code ec;
        fs::remove(tmp, ec);
        throw ImageIoError(path.string() + ": error: cannot write: " + err);
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw ImageIoError(path.string() + ": error: cannot write: " + ec.message());
    }
}

Image readImage(const fs::path& path) {
    using namespace OIIO;
    StderrCapture decoder;   // the decoders' own lines belong in the message
    auto in = ImageInput::open(path.string());
    if (!in) throw ImageIoError(path.string() + ": error: cannot read: " + withDecoderText(OIIO::geterror(), decoder.finish()));
    const ImageSpec& spec = in->spec();
    if (const auto problem = imageSizeProblem(spec.width, spec.height))
        throw ImageIoError(path.string() + ": error: cannot read: " + *problem);
    if (spec.nchannels <= 0 || spec.depth > 1 || spec.deep)
        throw ImageIoError(path.string() + ": error: cannot read: not a flat image with channels");
    const int channels = std::min(spec.nchannels, 4);   // rgba: further channels are never used
    std::vector<float> pixels(size_t(spec.width) * spec.height * size_t(channels));
    if (!in->read_image(0, 0, 0, channels, TypeDesc::FLOAT, pixels.data()))
        throw ImageIoError(path.string() + ": error: cannot read: " + withDecoderText(in->geterror(), decoder.finish()));
    in->close();
    (void)decoder.finish();
    Image image(spec.width, spec.height);
    for (size_t i = 0, n = size_t(spec.width) * spec.height; i < n; ++i)
        for (int c = 0; c < 4; ++c) {
            float v = c == 3 ? 1.0f : 0.0f;
            if (c < channels) v = pixels[i * size_t(channels) + size_t(c)];
            else if (c < 3 && channels < 3) v = pixels[i * size_t(channels)];
            image.rgba[i * 4 + size_t(c)] = v;
        }
    return image;
}

RenderMetadata readRenderMetadata(const fs::path& path) {
    using namespace OIIO;
    auto in = ImageInput::open(path.string());
    if (!in) throw ImageIoError(path.string() + ": error: cannot read: " + OIIO::geterror());
    const ImageSpec& spec = in->spec();
    const auto missing = [&](const char* name, const char* type) {
        return ImageIoError(path.string() + ": error: not an EXR that raylab-render wrote: no " + type + " attribute " +
                            name);
    };
    const auto integer = [&](const char* name) -> std::uint64_t {
        const ParamValue* p = spec.find_attribute(name, TypeDesc::INT);
        if (!p) p = spec.find_attribute(name, TypeDesc::UINT);
        if (!p) throw missing(name, "integer");
        const long long v = p->type() == TypeDesc::UINT ? (long long)p->get<unsigned>() : (long long)p->get<int>();
        if (v < 0) throw ImageIoError(path.string() + ": error: attribute " + name + " is negative");
        return std::uint64_t(v);
    };
    const auto text = [&](const char* name) {
        const ParamValue* p = spec.find_attribute(name, TypeDesc::STRING);
        if (!p) throw missing(name, "string");
        return std::string(p->get<ustring>().string());
    };
    if (lower(path.extension().string()) != ".exr" || std::string(in->format_name()) != "openexr")
        throw ImageIoError(path.string() + ": error: not an EXR that raylab-render wrote: a " +
                           std::string(in->format_name()) + " file");
    RenderMetadata m;
    m.version = text("raylab:version");
    m.settingsHash = text("raylab:settings_hash");
    m.spp = integer("raylab:spp");
    m.seed = std::uint32_t(integer("raylab:seed"));
    m.sceneFile = text("raylab:scene");
    m.sampler = text("raylab:sampler");
    for (std::string_view key : kEstimatorStageKeys) {
        const std::string stage(key.substr(key.find('.') + 1));
        if (const ParamValue* p = spec.find_attribute("raylab:" + stage, TypeDesc::STRING))
            m.stages.emplace_back(stage, p->get<ustring>().string());
    }
    m.nonFiniteSamples = integer("raylab:nonfinite_samples");
    m.targetSpp = integer("raylab:target_spp");
    m.rpp = int(integer("raylab:rpp"));
    m.passes = integer("raylab:passes");
    m.tracer = text("raylab:tracer");
    const ParamValue* seconds = spec.find_attribute("raylab:render_seconds", TypeDesc::FLOAT);
    if (!seconds) throw missing("raylab:render_seconds", "float");
    m.renderSeconds = seconds->get<float>();
    return m;
}

std::optional<AdaptiveState> readAdaptiveState(const fs::path& path) {
    using namespace OIIO;
    StderrCapture decoder;
    auto in = ImageInput::open(path.string());
    if (!in) throw ImageIoError(path.string() + ": error: cannot read: " + withDecoderText(OIIO::geterror(), decoder.finish()));
    const ImageSpec& spec = in->spec();
    // OpenEXR keeps channels sorted by name, and readers order them as they like: found by name.
    std::vector<int> at;
    for (std::size_t k = 4; k < kRgbaAndAdaptive.size(); ++k) {
        const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), kRgbaAndAdaptive[k]);
        at.push_back(it == spec.channelnames.end() ? -1 : int(it - spec.channelnames.begin()));
    }
    const auto found = std::count_if(at.begin(), at.end(), [](int c) { return c >= 0; });
    if (found == 0) {
        (void)decoder.finish();
        return std::nullopt;
    }
    for (std::size_t k = 0; k < at.size(); ++k)
        if (at[k] < 0)
            throw ImageIoError(path.string() + ": error: an adaptive render's EXR without its channel " +
                               kRgbaAndAdaptive[k + 4]);
    const ParamValue* gate = spec.find_attribute("raylab:adaptive_gate_closed_at", TypeDesc::INT);
    if (!gate) throw ImageIoError(path.string() + ": error: an adaptive render's EXR without its integer attribute "
                                  "raylab:adaptive_gate_closed_at");
    if (gate->get<int>() < 0) throw ImageIoError(path.string() + ": error: attribute raylab:adaptive_gate_closed_at is negative");
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    AdaptiveState state;
    state.gateClosedAt = std::uint64_t(gate->get<int>());
    state.half.resize(4 * pixels);
    state.samples.resize(pixels);
    std::vector<float> plane(pixels);
    for (std::size_t k = 0; k < 4; ++k) {
        if (!in->read_image(0, 0, at[k], at[k] + 1, TypeDesc::FLOAT, plane.data()))
            throw ImageIoError(path.string() + ": error: cannot read: " + withDecoderText(in->geterror(), decoder.finish()));
        for (std::size_t i = 0; i < pixels; ++i) state.half[4 * i + k] = plane[i];
    }
    if (!in->read_image(0, 0, at[4], at[4] + 1, TypeDesc::UINT32, state.samples.data()))
        throw ImageIoError(path.string() + ": error: cannot read: " + withDecoderText(in->geterror(), decoder.finish()));
    in->close();
    (void)decoder.finish();
    return state;
}

} // namespace raylab
