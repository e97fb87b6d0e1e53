// stb's PNG reader and writer, compiled once here from Debian's libstb-dev headers, so
// that the installed library needs no build-machine path to an archive.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
