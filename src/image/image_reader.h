#pragma once
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>

#include "image/image_signature.h"

namespace hipr {

// Opens `path` with the reader its first bytes name (image_signature.h), one of `accepted` (of
// the whole-image formats OpenExr, Radiance and Png), and no other. OpenImageIO alone, when the
// reader the file's extension names refuses it, offers the file to every reader it has, some of
// which trust whatever their header claims (fuzzing found a negative-size copy in the IFF reader).
// Every size a header claims is checked before anything is allocated for it: an OpenEXR header is
// walked before OpenEXR parses it (exr_header.h), and the opened image must have a channel, at most
// `max_texels` texels, and no more than its file can hold (plausible_image_size). A file of another
// format or of none, or a claim beyond those, is an InputError in one line naming `what`.
std::unique_ptr<OIIO::ImageInput> open_image_reader(const std::filesystem::path& path,
                                                    std::initializer_list<ImageFormat> accepted,
                                                    const std::string& what, int64_t max_texels);

// Reads the opened image's first three channels as packed RGB floats into `rgb` (width x height
// triples, rows top first). A grey image, alone or with alpha (one or two channels), gives its
// grey in all three. A decoding failure is an InputError naming `what`.
void read_rgb(OIIO::ImageInput& input, float* rgb, const std::string& what);

}  // namespace hipr
