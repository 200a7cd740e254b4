#pragma once
// Writing a patched glTF document as .glb or .gltf, each file atomically (temp + rename).
//
// .glb: one self-contained file. Buffer 0 becomes the BIN chunk (read from the source's BIN
// chunk, file or data: URI); images stored as files or data: URIs are appended to it as new
// buffer views (with their mimeType), and so is every further buffer (its views then point at
// buffer 0, which is all the document keeps). Indices of views and images never change, so
// nothing else in the document moves.
//
// .gltf: into the source's own folder, the document keeps referencing the source's side files
// by their URIs. Into another folder, every side file is copied beside it under the same
// relative URI (a copy that would replace a different existing file is refused: it may belong
// to another scene). A .glb source's BIN chunk becomes "<output stem>.bin" beside the output.
// The source's own side files are never written.
#include <filesystem>

#include "scene/gltf_source.h"

namespace hipr::gltf {

void write_glb(const SourceDocument& source, Json doc, const std::filesystem::path& path);
void write_gltf(const SourceDocument& source, Json doc, const std::filesystem::path& path);

// Absolute, symlink-resolved paths of the source's own side files (and the source itself).
std::vector<std::filesystem::path> source_files(const SourceDocument& source);

}  // namespace hipr::gltf
