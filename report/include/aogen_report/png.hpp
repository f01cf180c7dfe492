// aogen_report/png.hpp — 8-bit RGB images and their PNG bytes (Debian's stb_image_write).
//
//     aogen_report::rgb_image img(width, height);          // black
//     img.set(x, y, {255, 128, 0});
//     std::string bytes = aogen_report::encode_png(img);   // deterministic: same pixels, same bytes
//     std::string grey = aogen_report::encode_png(w, h, 1, levels); // 1 to 4 channels of bytes
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

// PNG bytes of `pixels`: `channels` bytes per pixel (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA),
// row-major, top row first.
inline std::string encode_png(int width, int height, int channels, const std::vector<uint8_t>& pixels)
{
    if (width < 1 || height < 1 || channels < 1 || channels > 4 || pixels.size() != size_t(width) * height * channels)
        aogen::fail("png", std::to_string(width) + "x" + std::to_string(height) + " with " + std::to_string(pixels.size()) + " bytes of " +
                               std::to_string(channels) + " channels",
                    "valid: width, height >= 1, 1 to 4 channels and that many bytes per pixel");
    std::string out;
    const auto append = [](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size)); };
    if (!stbi_write_png_to_func(append, &out, width, height, channels, pixels.data(), width * channels))
        aogen::fail("png", "the encoder failed", "valid: a smaller image");
    return out;
}

inline std::string encode_png(const rgb_image& img) { return encode_png(img.width, img.height, 3, img.pixels); }

} // namespace aogen_report
