// stb's PNG reader, compiled once here from Debian's libstb-dev headers, so that the
// installed library needs no build-machine path to an archive (the writer is
// Tidewater::bake's, stb_write_implementation.cpp).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
