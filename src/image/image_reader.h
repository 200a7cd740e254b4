#pragma once
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>

namespace hipr {

// The whole-image formats hipr reads: renders and references to compare, environment maps.
enum class ImageFormat { OpenExr, Radiance, Png };

// Opens `path` with the reader its first bytes name, one of `accepted`, and no other. OpenImageIO
// alone, when the reader the file's extension names refuses it, offers the file to every reader
// it has, some of which trust whatever their header claims (fuzzing found a negative-size copy
// in the IFF reader). A file of another format, or of none, is an InputError naming `what` and
// the formats accepted.
std::unique_ptr<OIIO::ImageInput> open_image_reader(const std::filesystem::path& path,
                                                    std::initializer_list<ImageFormat> accepted,
                                                    const std::string& what);

}  // namespace hipr
