// The page's text helpers (aogen_report/html_text.hpp, text_table.hpp) against RFC 4648's
// base64 test vectors and hand-worked HTML.
#include <aogen_report/html_text.hpp>
#include <aogen_report/svg_plot.hpp>
#include <aogen_report/text_table.hpp>

#include <catch2/catch.hpp>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_html_text_test {

using namespace aogen_report;

TEST_CASE("html text: base64 gives RFC 4648's test vectors, and every byte value")
{
    // RFC 4648, section 10.
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("fooba") == "Zm9vYmE=");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\xfe\x00", 3)) == "//4A"); // high bytes, and a NUL, are bytes
}

TEST_CASE("html text: escaping leaves no markup and keeps every other character")
{
    CHECK(html_escape("<script>alert('x') & \"y\"</script>") == "&lt;script&gt;alert(&#39;x&#39;) &amp; &quot;y&quot;&lt;/script&gt;");
    CHECK(html_escape("1920×1080 — ✓") == "1920×1080 — ✓");
}

TEST_CASE("html text: the report's Markdown marks become HTML, everything else is escaped")
{
    CHECK(html_from_markdown("**How to read it.** *Default*: `-nearest` <b>") ==
          "<strong>How to read it.</strong> <em>Default</em>: <code>-nearest</code> &lt;b&gt;");
    CHECK(html_from_markdown("`a*b*c` and `<x>`") == "<code>a*b*c</code> and <code>&lt;x&gt;</code>"); // no marks inside code
    CHECK(html_from_markdown("ao^p * 2, an unpaired ` and **") == "ao^p * 2, an unpaired ` and **");
    CHECK(html_from_markdown("**Device: <i>x</i>**") == "<strong>Device: &lt;i&gt;x&lt;/i&gt;</strong>");
}

TEST_CASE("text table: one table as Markdown and as HTML, a ragged row refused")
{
    text_table t{{"scene", "RMSE"}, "lr", {{"`<crease>`", "0.0500"}}};
    CHECK(markdown_table(t) == "| scene | RMSE |\n|---|---:|\n| `<crease>` | 0.0500 |\n");
    CHECK(html_table(t) == "<table>\n<thead><tr><th>scene</th><th class=\"num\">RMSE</th></tr></thead>\n<tbody>\n"
                           "<tr><td><code>&lt;crease&gt;</code></td><td class=\"num\">0.0500</td></tr>\n</tbody>\n</table>\n");
    t.rows.push_back({"only one cell"});
    CHECK_THROWS_WITH(markdown_table(t), Catch::Contains("one cell and one alignment per column"));
}

TEST_CASE("svg plot: short names, log ticks and their text")
{
    CHECK(plot_label("gtao-2x2-half-denoise-gbufworld-std-persp-cs") == "gtao-2x2-half-denoise");
    CHECK(plot_label("ssao-s16") == "ssao-s16");
    CHECK(detail::log_ticks(0.03, 0.7) == std::vector<double>{0.05, 0.1, 0.2, 0.5});
    CHECK(detail::tick_text(0.05) == "0.05");
    CHECK(detail::tick_text(2) == "2");
    CHECK(detail::tick_text(0.025) == "0.025");
    CHECK(detail::linear_step(0.13) == Approx(0.02));
}

} // namespace unity_html_text_test
