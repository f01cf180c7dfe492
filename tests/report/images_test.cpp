// Report images: nearest upsampling, the colour ramps, text, and labelled strips whose PNG
// bytes are decoded back with stb_image (a separate decoder) and checked pixel by pixel.
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

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_images_test {

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

namespace {

rgb pixel(const rgb_image& img, int x, int y)
{
    const uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 3];
    return {p[0], p[1], p[2]};
}

rgb_image decode(const std::string& png)
{
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()), int(png.size()), &w, &h, &channels, 3);
    REQUIRE(data != nullptr);
    rgb_image img(w, h);
    img.pixels.assign(data, data + size_t(w) * h * 3);
    stbi_image_free(data);
    return img;
}

// How many pixels of `img` in columns [x0, x1) and rows [y0, y1) are `colour`.
int count(const rgb_image& img, int x0, int y0, int x1, int y1, rgb colour)
{
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += pixel(img, x, y) == colour;
    return n;
}

// The columns [first, last] that hold `colour`; {-1, -1} when none does.
std::pair<int, int> ink_columns(const rgb_image& img, rgb colour)
{
    int first = -1, last = -1;
    for (int x = 0; x < img.width; ++x)
        if (count(img, x, 0, x + 1, img.height, colour) > 0) {
            if (first < 0) first = x;
            last = x;
        }
    return {first, last};
}

rgb_image text_image(const std::string& text, int scale, int width = 200, int height = 30)
{
    rgb_image img(width, height, {255, 255, 255});
    draw_text(img, 0, 0, text, {0, 0, 0}, scale);
    return img;
}

// A w × h test pattern: reference ramps up, the variant down, pixel 5 is background.
struct row_images {
    std::vector<float> reference, ao;
    std::vector<uint8_t> valid;
    row_images(int w, int h) : reference(size_t(w) * h), ao(size_t(w) * h), valid(size_t(w) * h, 1)
    {
        for (int i = 0; i < w * h; ++i) reference[i] = float(i) / float(w * h), ao[i] = 1.0f - reference[i];
        valid[5] = 0;
    }
};

// The longest kind of label the report writes.
const std::string long_label = strip_label("gtao-2x3-half-box-gbufworld-std-persp-cs", 0.05, 0.0761);

// A strip of w × h row_images rows (reference | variant), one per label, through PNG and back.
rgb_image labelled_strip(int w, int h, const std::vector<std::string>& labels)
{
    const row_images a(w, h);
    strip s(w, h);
    for (const std::string& label : labels) s.add_row(a.reference, a.ao, a.valid, label);
    return decode(encode_png(s.image()));
}

// Pixels where `img`, from (x, y) on, disagrees with `alone` (black text on white) on
// whether they are text.
int text_mismatches(const rgb_image& img, int x, int y, const rgb_image& alone)
{
    int n = 0;
    for (int ay = 0; ay < alone.height; ++ay)
        for (int ax = 0; ax < alone.width && x + ax < img.width; ++ax)
            n += (pixel(img, x + ax, y + ay) == label_text_colour) != (pixel(alone, ax, ay) == rgb{0, 0, 0});
    return n;
}

} // namespace

TEST_CASE("images: text is printable ASCII, one '?' for each character the font lacks")
{
    CHECK(printable("gtao-2x3 0.050 ms") == "gtao-2x3 0.050 ms");
    CHECK(printable("na\xC3\xAFve") == "na?ve");            // ï: two UTF-8 bytes, one '?'
    CHECK(printable("\xE6\x97\xA5\xE6\x9C\xAC") == "??"); // 日本: three bytes each
    CHECK(printable("a\tb\x7F\n") == "a?b??");            // control characters and DEL
    CHECK(printable("\x80x") == "?x");                     // a stray continuation byte
    CHECK(printable("") == "");
    // What is drawn for a non-ASCII label is exactly what is drawn for its '?' form.
    CHECK(text_image("na\xC3\xAFve \xF0\x9F\x99\x82", 1).pixels == text_image("na?ve ?", 1).pixels);
    CHECK(text_width("na\xC3\xAFve", 1) == text_width("na?ve", 1));
}

TEST_CASE("images: text width grows with its length and scale, ink stays in its box")
{
    // Digits and lowercase 'a'..'c' advance 6 font units each.
    CHECK(text_width("abc", 1) == 18);
    CHECK(text_width("abc", 2) == 36);
    CHECK(text_width("", 3) == 0);
    CHECK(text_height(1) == 9);
    CHECK(text_height(7) == 63);
    int last = -1;
    for (const std::string text : {"0", "01", "0123", "01234567"}) {
        const rgb_image img = text_image(text, 1);
        const auto [first_ink, last_ink] = ink_columns(img, {0, 0, 0});
        CHECK(first_ink >= 0);
        CHECK(last_ink > last); // rendered width grows with the label's length
        CHECK(last_ink < text_width(text, 1));
        CHECK(count(img, 0, text_height(1), img.width, img.height, {0, 0, 0}) == 0); // nothing below the glyph rows
        last = last_ink;
    }
    CHECK(count(text_image("", 1), 0, 0, 200, 30, {0, 0, 0}) == 0);
}

TEST_CASE("images: text at scale 2 is the scale-1 text with each pixel doubled, clipped at the edges")
{
    const std::string text = "RMSE 0.0761 gjpqy";
    const rgb_image one = text_image(text, 1, 120, 12), two = text_image(text, 2, 240, 24);
    for (int y = 0; y < two.height; ++y)
        for (int x = 0; x < two.width; ++x) CHECK(pixel(two, x, y) == pixel(one, x / 2, y / 2));
    // Drawn from outside the image: the part inside is the same pixels, shifted.
    rgb_image clipped(40, 6, {255, 255, 255});
    draw_text(clipped, -10, -3, text, {0, 0, 0}, 1);
    for (int y = 0; y < clipped.height; ++y)
        for (int x = 0; x < clipped.width; ++x) CHECK(pixel(clipped, x, y) == pixel(one, x + 10, y + 3));
}

TEST_CASE("images: a strip label shows the name, the time and the RMSE, n/a where there is none")
{
    CHECK(strip_label("gtao-2x3-half-box-gbufworld-std-persp-cs", 0.05, 0.0761) == "gtao-2x3-half-box-gbufworld-std-persp-cs  0.050 ms  RMSE 0.0761");
    CHECK(strip_label("ssao", 12.34567, 0.1) == "ssao  12.346 ms  RMSE 0.1000");
    CHECK(strip_label("ssao", std::nan(""), std::nan("")) == "ssao  n/a ms  RMSE n/a");
}

TEST_CASE("images: the text scale and label band follow the panel height")
{
    CHECK(strip_text_scale(36) == 1);
    CHECK(strip_text_scale(159) == 1);
    CHECK(strip_text_scale(180) == 2);
    CHECK(strip_text_scale(1080) == 7);
    CHECK(strip(64, 36).band_height() == 13); // 9 rows of glyph, 2 of margin each side
    CHECK(strip(320, 180).band_height() == 26);
    CHECK(strip(1920, 1080).band_height() == 91);
}

TEST_CASE("images: a strip encodes to a PNG that decodes to its labelled rows, panels value by value")
{
    const int w = 64, h = 36;
    const row_images a(w, h);
    const std::string label = strip_label("ssao-8-full", 0.05, 0.0761);
    const auto three_rows = [&] {
        strip s(w, h);
        s.add_row(a.reference, a.ao, a.valid, label);
        s.add_row(a.ao, a.ao, a.valid, "");
        s.add_row(a.reference, a.reference, a.valid, "gtao");
        return s.image();
    };
    const rgb_image img = three_rows();
    const int band = 13, pitch = band + h + strip_gap;
    // The label (27 characters) is narrower than the panels: the width is theirs.
    REQUIRE(text_width(label, 1) + 4 < 3 * w + 2 * strip_gap);
    CHECK(img.width == 3 * w + 2 * strip_gap);
    CHECK(img.height == 3 * (band + h) + 2 * strip_gap);
    const std::string png = encode_png(img);
    CHECK(png.substr(1, 3) == "PNG");
    const rgb_image decoded = decode(png);
    REQUIRE(decoded.width == img.width);
    REQUIRE(decoded.height == img.height);
    CHECK(decoded.pixels == img.pixels);

    const std::vector<float>* references[3] = {&a.reference, &a.ao, &a.reference};
    const std::vector<float>* variants[3] = {&a.ao, &a.ao, &a.reference};
    for (int r = 0; r < 3; ++r) {
        const int top = r * pitch;
        // The band: text pixels inside its margins only, band colour everywhere else.
        const int text_pixels = count(decoded, 0, top, img.width, top + band, label_text_colour);
        CHECK(text_pixels == count(decoded, 2, top + 2, img.width - 2, top + 2 + text_height(1), label_text_colour));
        CHECK(count(decoded, 0, top, img.width, top + band, label_band_colour) + text_pixels == img.width * band);
        if (r == 1) CHECK(text_pixels == 0); // the empty label
        else CHECK(text_pixels > 20);
        // The panels under it, every pixel.
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x;
                const float ref = (*references[r])[i], ao = (*variants[r])[i];
                const bool valid = a.valid[i] != 0;
                CHECK(pixel(decoded, x, top + band + y) == (valid ? grey(ref) : background_colour));
                CHECK(pixel(decoded, w + strip_gap + x, top + band + y) == (valid ? grey(ao) : background_colour));
                CHECK(pixel(decoded, 2 * (w + strip_gap) + x, top + band + y) == (valid ? heat(ao - ref, heat_full_scale) : background_colour));
            }
    }
    CHECK(pixel(decoded, 5, band) == background_colour); // pixel 5 is background
    CHECK(text_mismatches(decoded, 2, 2, text_image(label, 1, img.width - 2, text_height(1))) == 0);
    // The longer label has more ink than the shorter one.
    CHECK(count(decoded, 0, 0, img.width, band, label_text_colour) > count(decoded, 0, 2 * pitch, img.width, 2 * pitch + band, label_text_colour));
    CHECK(encode_png(three_rows()) == png); // deterministic: the same strip again, the same bytes
}

TEST_CASE("images: a label wider than the panels widens the strip, its panels stay at the left")
{
    const int w = 64, h = 36, band = 13, panels_width = 3 * w + 2 * strip_gap;
    const row_images a(w, h);
    const rgb_image img = labelled_strip(w, h, {"short", long_label});
    CHECK(img.width == text_width(long_label, 1) + 2 * strip_label_margin);
    CHECK(img.width > panels_width);
    CHECK(img.height == 2 * (band + h) + strip_gap);
    // The long label's ink reaches past the panels; the short one's does not.
    const rgb_image long_alone = text_image(long_label, 1, img.width, text_height(1)), short_alone = text_image("short", 1, img.width, text_height(1));
    CHECK(ink_columns(long_alone, {0, 0, 0}).second > panels_width);
    CHECK(ink_columns(short_alone, {0, 0, 0}).second < 40);
    for (int r = 0; r < 2; ++r) {
        const int top = r * (band + h + strip_gap);
        // Each label in its band is the text drawn alone, moved by the margin.
        CHECK(text_mismatches(img, 2, top + 2, r == 0 ? short_alone : long_alone) == 0);
        CHECK(pixel(img, 1, top + band) == grey(a.reference[1]));
        CHECK(pixel(img, 2 * (w + strip_gap) + 1, top + band) == heat(a.ao[1] - a.reference[1], heat_full_scale));
        // Right of the panels: white, as the gaps.
        CHECK(count(img, panels_width, top + band, img.width, top + band + h, {255, 255, 255}) == (img.width - panels_width) * h);
    }
}

TEST_CASE("images: at 320x180 the label is drawn at scale 2 in a 26-row band")
{
    const int w = 320, h = 180;
    const row_images a(w, h);
    const rgb_image img = labelled_strip(w, h, {long_label});
    CHECK(img.width == 3 * w + 2 * strip_gap); // 2 · the label's width fits
    CHECK(img.height == 26 + h);
    CHECK(text_mismatches(img, 4, 4, text_image(long_label, 2, img.width - 4, text_height(2))) == 0);
    CHECK(count(img, 0, 0, img.width, 26, label_text_colour) > 400);
    CHECK(pixel(img, 1, 26) == grey(a.reference[1]));
}

} // namespace unity_images_test
