// stb's PNG writer, compiled once here from Debian's libstb-dev headers (the reader is
// Tidewater::core's, stb_implementation.cpp).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
