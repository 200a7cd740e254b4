#include "image/image_reader.h"

#include <algorithm>
#include <array>
#include <fstream>

#include "core/error.h"
#include "image/exr_header.h"
#include "image/png_chunks.h"

namespace hipr {
namespace {

// OpenImageIO's reader for each whole-image format hipr reads.
const char* reader_of(ImageFormat format) {
  switch (format) {
    case ImageFormat::OpenExr:
      return "openexr";
    case ImageFormat::Radiance:
      return "hdr";
    case ImageFormat::Png:
      return "png";
    default:
      throw InternalError("open_image_reader: no whole-image reader for this format");
  }
}

// "A", "A or B", "A, B or C": the formats a use accepts, for its error message.
std::string names_of(std::initializer_list<ImageFormat> accepted) {
  std::string names;
  size_t named = 0;
  for (const ImageFormat format : accepted) {
    ++named;
    names += std::string(named == 1                 ? ""
                         : named == accepted.size() ? " or "
                                                    : ", ") +
             image_format_name(format);
  }
  return names;
}

}  // namespace

std::unique_ptr<OIIO::ImageInput> open_image_reader(const std::filesystem::path& path,
                                                    std::initializer_list<ImageFormat> accepted,
                                                    const std::string& what, int64_t max_texels) {
  const std::string named = what + " " + path.string();
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read " + named);
  std::array<char, kImageSignatureBytes> head{};
  file.read(head.data(), std::streamsize(head.size()));
  const std::optional<ImageFormat> format =
      image_format_of(reinterpret_cast<const unsigned char*>(head.data()), size_t(file.gcount()));
  if (!format || std::find(accepted.begin(), accepted.end(), *format) == accepted.end())
    throw InputError(named + " is not " + names_of(accepted));

  std::error_code ec;
  const uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError("cannot read " + named + ": " + ec.message());
  const auto check_size = [&](int64_t width, int64_t height) {
    const std::string claim = "(" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (width < 1 || height < 1) throw InputError(named + " has no texels " + claim);
    if (!plausible_image_size(width, height, bytes))
      throw InputError(named + " claims more texels " + claim + " than its " +
                       std::to_string(bytes) + " bytes can hold");
    if (double(width) * double(height) > double(max_texels))
      throw InputError(named + " is larger " + claim + " than hipr reads (" +
                       std::to_string(max_texels) + " texels)");
  };
  // OpenEXR allocates by its header's claims while parsing it: they are checked before.
  if (*format == ImageFormat::OpenExr)
    if (const auto window = scan_exr_header(path)) check_size(window->width, window->height);
  // libpng allocates each chunk at the length it claims: the claims are checked first too.
  if (*format == ImageFormat::Png) scan_png_chunks(file, bytes, named);

  const char* reader = reader_of(*format);
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(reader);
  if (!input) throw InternalError(std::string("OpenImageIO has no ") + reader + " reader");
  OIIO::ImageSpec spec;
  // Colours as the file stores them: OpenImageIO would multiply a PNG's by its alpha, which is
  // not a colour (`compare` judged a translucent pixel's colour scaled by its alpha). OpenEXR and
  // Radiance store no unassociated alpha: the hint changes nothing there.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  if (!input->open(path.string(), spec, config))
    throw InputError("cannot read " + named + ": " + input->geterror());
  if (input->spec().nchannels < 1) throw InputError(named + " has no channels");
  check_size(input->spec().width, input->spec().height);
  return input;
}

void read_rgb(OIIO::ImageInput& input, float* rgb, const std::string& what) {
  const OIIO::ImageSpec& spec = input.spec();
  // The first three channels only, straight into the triples: a header naming thousands of
  // channels costs no more memory.
  const int channels = std::min(spec.nchannels, 3);
  constexpr OIIO::stride_t kTriple = 3 * sizeof(float);
  if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, rgb, kTriple))
    throw InputError("cannot decode " + what + ": " + input.geterror());
  if (channels == 3) return;
  const size_t texels = size_t(spec.width) * size_t(spec.height);
  for (size_t i = 0; i < texels; ++i) rgb[3 * i + 1] = rgb[3 * i + 2] = rgb[3 * i];
}

}  // namespace hipr
