// aogen_report/png.hpp — 8-bit RGB images and their PNG bytes (Debian's stb_image_write).
//
//     aogen_report::rgb_image img(width, height);          // black
//     img.set(x, y, {255, 128, 0});
//     std::string bytes = aogen_report::encode_png(img);   // deterministic: same pixels, same bytes
//
// The encoder is compiled into each translation unit that includes this header (static
// functions), so any number of programs and tests may include it.
#pragma once

#include <aogen/error.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace aogen_report {

using rgb = std::array<uint8_t, 3>;

struct rgb_image {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels; // row-major, top row first, 3 bytes per pixel

    rgb_image() = default;
    rgb_image(int w, int h, rgb fill = {0, 0, 0}) : width(w), height(h), pixels(size_t(w) * h * 3)
    {
        for (size_t i = 0; i < pixels.size(); i += 3) pixels[i] = fill[0], pixels[i + 1] = fill[1], pixels[i + 2] = fill[2];
    }
    void set(int x, int y, rgb c)
    {
        uint8_t* p = &pixels[(size_t(y) * width + x) * 3];
        p[0] = c[0], p[1] = c[1], p[2] = c[2];
    }
};

inline std::string encode_png(const rgb_image& img)
{
    if (img.width < 1 || img.height < 1 || img.pixels.size() != size_t(img.width) * img.height * 3)
        aogen::fail("png", std::to_string(img.width) + "x" + std::to_string(img.height) + " with " + std::to_string(img.pixels.size()) + " bytes",
                    "valid: width, height >= 1 and 3 bytes per pixel");
    std::string out;
    const auto append = [](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size)); };
    if (!stbi_write_png_to_func(append, &out, img.width, img.height, 3, img.pixels.data(), img.width * 3))
        aogen::fail("png", "the encoder failed", "valid: a smaller image");
    return out;
}

} // namespace aogen_report
