// The single translation unit that compiles tinygltf. Image decoding comes from Debian's libstb.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
