/* stb_image's implementation, compiled only when the build uses the vendored stb (the Makefile's
 * STB setting); a system stb (Debian's libstb-dev) ships it compiled, as libstb. */
#define STB_IMAGE_IMPLEMENTATION
#include "stb_image.h"
