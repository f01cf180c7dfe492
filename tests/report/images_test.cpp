// Report images: nearest upsampling, the colour ramps, and PNG bytes decoded back with
// stb_image (a separate decoder) to the pixels that were encoded.
#include <aogen_report/images.hpp>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#pragma GCC diagnostic pop

#include <catch2/catch.hpp>

using namespace aogen_report;

TEST_CASE("images: half resolution upsamples to full by reading pixel x / 2, odd sizes included")
{
    // 3×2 half-res image of a 5×3 frame: values = 10·y + x.
    const std::vector<float> half{0, 1, 2, 10, 11, 12};
    const std::vector<float> full = upsample(half, 3, 2, 2, 5, 3);
    REQUIRE(full.size() == 15);
    const float expected[3][5] = {{0, 0, 1, 1, 2}, {0, 0, 1, 1, 2}, {10, 10, 11, 11, 12}};
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) CHECK(full[size_t(y) * 5 + x] == expected[y][x]);
    CHECK(upsample(half, 3, 2, 1, 3, 2) == half);
    CHECK_THROWS_WITH(upsample(half, 3, 2, 2, 7, 3), Catch::Contains("w = ceil(W / factor)"));
}

TEST_CASE("images: grey and heat ramps end where documented, non-finite is magenta")
{
    CHECK(grey(0.0f) == rgb{0, 0, 0});
    CHECK(grey(1.0f) == rgb{255, 255, 255});
    CHECK(grey(0.5f) == rgb{128, 128, 128});
    CHECK(grey(std::nanf("")) == rgb{255, 0, 255});
    CHECK(heat(0.0f, 0.5f) == rgb{0, 0, 0});
    CHECK(heat(-0.5f, 0.5f) == rgb{255, 250, 160});
    CHECK(heat(2.0f, 0.5f) == rgb{255, 250, 160});
    CHECK(heat(0.5f / 3, 0.5f) == rgb{120, 28, 160});
}

TEST_CASE("images: a strip encodes to a PNG that decodes to the same pixels")
{
    const int w = 4, h = 3;
    std::vector<float> reference(w * h), ao(w * h);
    std::vector<uint8_t> valid(w * h, 1);
    for (int i = 0; i < w * h; ++i) reference[i] = float(i) / (w * h), ao[i] = 1.0f - reference[i];
    valid[5] = 0;
    strip s(w, h);
    s.add_row(reference, ao, valid);
    s.add_row(ao, ao, valid);
    const rgb_image img = s.image();
    CHECK(img.width == 3 * w + 2 * strip_gap);
    CHECK(img.height == 2 * h + strip_gap);
    const std::string png = encode_png(img);
    CHECK(png.substr(1, 3) == "PNG");
    int dw = 0, dh = 0, channels = 0;
    unsigned char* decoded = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()), int(png.size()), &dw, &dh, &channels, 3);
    REQUIRE(decoded != nullptr);
    CHECK(dw == img.width);
    CHECK(dh == img.height);
    CHECK(std::vector<uint8_t>(decoded, decoded + size_t(dw) * dh * 3) == img.pixels);
    stbi_image_free(decoded);
    // Pixel (1, 0) of row 0: reference grey, variant grey, heat of their difference.
    const auto at = [&](int x, int y) { const uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 3]; return rgb{p[0], p[1], p[2]}; };
    CHECK(at(1, 0) == grey(reference[1]));
    CHECK(at(w + strip_gap + 1, 0) == grey(ao[1]));
    CHECK(at(2 * (w + strip_gap) + 1, 0) == heat(ao[1] - reference[1], heat_full_scale));
    CHECK(at(1, 1) == background_colour); // pixel 5 is background
    CHECK(encode_png(img) == png);        // deterministic
}
