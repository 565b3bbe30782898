// The render component alone: pictures need only the core (pkg-config contactfx-render, with no scene
// library). Encodes a 2 x 2 image and checks the PNG signature.
#include <contactfx/render/png.h>
#include <cstdio>
#include <string>

int main()
{
    const unsigned char pixels[2 * 2 * 4] = {255, 0, 0,   255, 0,   255, 0,   255,
                                             0,   0, 255, 255, 255, 255, 255, 255};
    const std::string png = cfx::render::EncodePng(pixels, 2, 2, 2 * 4);
    if (png.size() < 8 || png.compare(1, 3, "PNG") != 0)
    {
        std::fprintf(stderr, "consumer_render: not a PNG\n");
        return 1;
    }
    std::printf("consumer_render: a %zu-byte PNG\n", png.size());
    return 0;
}
