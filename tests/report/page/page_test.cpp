// tests/report/page/page_test.cpp — the report's pages in a real browser: Debian's
// chromium, headless, driven through the DevTools protocol (browser.hpp).
//
// A report made here by hand (six variants on two scenes, one of them named like a script
// tag) is written as report.html and opened; the checks are what a reader does with it:
// no console error; one marker per variant with a time and an error, in each panel;
// hovering a marker (real mouse events) names its variant; a column's button sorts the
// table both ways; a filter hides the other rows and fades their markers; selecting a row
// draws reference | variant | |error| per scene with the right pixels; the script-tag
// scene name shows as text and never runs. The stability suite's page likewise.
//
// Two tests are hidden ([.]) and run from elsewhere: "a report made by aogen_report"
// (report_test.sh, on a real report: AOGEN_PAGE names its report.html) and "screenshot"
// (docs/report_page.png: AOGEN_PAGE and AOGEN_PAGE_SCREENSHOT).
#include "browser.hpp"

#include <aogen_report/page.hpp>
#include <aogen_report/pareto.hpp>
#include <aogen_report/suite_page.hpp>

#include <aogen/variant.hpp>
#include <aogen_tools/files.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* script_scene = "<script>window.injected = 1</script>";

// A scene of w × h pixels whose reference is a left-to-right ramp, its first column background.
aogen_report::scene_record scene_of(const std::string& name, int w, int h)
{
    aogen_report::scene_record s;
    s.scene.name = name;
    s.scene.camera.width = w, s.scene.camera.height = h;
    s.truth.width = w, s.truth.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            s.truth.valid.push_back(x > 0);
            s.truth.ao.push_back(x > 0 ? float(x) / float(w) : NAN);
        }
    s.valid_pixels = size_t(w - 1) * h;
    return s;
}

struct made_variant {
    const char* name;
    double ms, rmse, rmse_calibrated;
};

// Six variants: distinct times and errors, one without a time (no marker), and one not run
// on the second scene.
const made_variant made[] = {
    {"gtao-2x2-half-denoise-gbufworld-std-persp-cs", 0.07, 0.062, 0.058},
    {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", 0.21, 0.072, 0.064},
    {"vbao-2x3-half-bilateral-gbufworld-std-persp-cs", 0.52, 0.055, 0.052},
    {"sao-s8-full-denoise-gbufworld-std-persp-fs", 1.5, 0.090, 0.081},
    {"gtao-4x4-full-noblur-gbufworld-std-persp-cs", NAN, 0.050, 0.047},
    {"ssao-s8-full-box-gbufworld-std-persp-cs", 3.0, 0.120, 0.101},
};
constexpr size_t made_count = sizeof made / sizeof made[0];

aogen_report::report_data small_report()
{
    aogen_report::report_data d;
    d.device = "a <b>device</b> & co";
    d.grid = 32;
    d.frames = 8; // a third panel: the error after 8 frames (here 0.9 of the single frame's)
    d.scenes = {scene_of("crease", 16, 8), scene_of(script_scene, 16, 8)};
    std::vector<double> ms, rmse, rmse_calibrated, rmse_accumulated;
    for (const made_variant& m : made) {
        aogen_report::variant_record v;
        v.v = aogen::variant_from_name(m.name);
        v.name = m.name;
        v.passes = {"ao", "blur"};
        v.ms = m.ms, v.ms_p10 = m.ms * 0.9, v.ms_p90 = m.ms * 1.2, v.floor_ratio = 2, v.bandwidth_ratio = 4;
        v.rmse = m.rmse, v.rmse_calibrated = m.rmse_calibrated, v.rmse_accumulated = 0.9 * m.rmse, v.ao_instructions = 1000;
        for (size_t s = 0; s < d.scenes.size(); ++s) {
            aogen_report::run_record r;
            if (std::string(m.name).rfind("ssao-s8-full-box", 0) == 0 && s == 1) r.skipped = "planted: not run here";
            r.ms.median = m.ms, r.ms.p10 = m.ms * 0.9, r.ms.p90 = m.ms * 1.2;
            r.pass_ms = {r.ms, r.ms};
            r.plain.rmse = m.rmse, r.calibrated.rmse = m.rmse_calibrated, r.accumulated.rmse = 0.9 * m.rmse;
            const int factor = v.v.half_resolution ? 2 : 1;
            r.ao.width = 16 / factor, r.ao.height = 8 / factor, r.ao.factor = factor;
            for (int i = 0; i < r.ao.width * r.ao.height; ++i) r.ao.unorm.push_back(uint8_t(i * 7 % 256)); // every texel its own value
            v.runs.push_back(r);
        }
        d.variants.push_back(v);
        ms.push_back(m.ms), rmse.push_back(m.rmse), rmse_calibrated.push_back(m.rmse_calibrated), rmse_accumulated.push_back(0.9 * m.rmse);
    }
    const std::vector<bool> front = aogen_report::pareto_optimal(ms, rmse), front_calibrated = aogen_report::pareto_optimal(ms, rmse_calibrated),
                            front_accumulated = aogen_report::pareto_optimal(ms, rmse_accumulated);
    for (size_t i = 0; i < d.variants.size(); ++i)
        d.variants[i].pareto = front[i], d.variants[i].pareto_calibrated = front_calibrated[i], d.variants[i].pareto_accumulated = front_accumulated[i];
    return d;
}

// A folder of its own, removed at the end.
struct scratch {
    fs::path dir;
    scratch()
    {
        char name[] = "/tmp/aogen_page_test.XXXXXX";
        REQUIRE(::mkdtemp(name));
        dir = name;
    }
    ~scratch()
    {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

// `file` opened in `b`, its script finished.
void open_page(aogen_test::browser& b, const fs::path& file)
{
    b.open("file://" + file.string());
    CHECK(b.evaluate("document.body.dataset.ready || ''") == "true");
}

std::string chromium() { return AOGEN_CHROMIUM; }

// A page written to a folder of its own and opened in a fresh browser.
struct opened_page {
    scratch folder;
    aogen_test::browser b{chromium()};
    explicit opened_page(const std::string& html)
    {
        aogen::tools::write_file(folder.dir / "report.html", html);
        open_page(b, folder.dir / "report.html");
    }
};

// The hand-made report as its page, opened.
struct opened_report : opened_page {
    opened_report() : opened_page(aogen_report::report_page(small_report(), {"aogen_report --scenes '<script>x</script>'", true})) {}
};

// The centre of the first element matching `selector`, scrolled into view, in viewport pixels.
std::pair<double, double> centre_of(aogen_test::browser& b, const std::string& selector)
{
    const json r = b.evaluate("(() => { const e = document.querySelector(" + json(selector).dump() +
                              "); e.scrollIntoView({block: 'center'}); const r = e.getBoundingClientRect(); "
                              "return [r.left + r.width / 2, r.top + r.height / 2]; })()");
    return {r[0].get<double>(), r[1].get<double>()};
}

// The table's rows' variant indices as shown, top to bottom (hidden rows left out).
std::vector<int> row_order(aogen_test::browser& b)
{
    return b.evaluate("Array.from(document.querySelectorAll('#variant-table tbody tr')).filter(r => !r.hidden).map(r => Number(r.dataset.variant))")
        .get<std::vector<int>>();
}

// Variant indices sorted by `key`, ascending, those without one last.
std::vector<int> sorted_by(double made_variant::*key, bool ascending)
{
    std::vector<int> order;
    for (size_t i = 0; i < made_count; ++i) order.push_back(int(i));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const double x = made[a].*key, y = made[b].*key;
        if (std::isfinite(x) != std::isfinite(y)) return std::isfinite(x);
        return ascending ? x < y : x > y;
    });
    return order;
}

// A real click on the centre of the first element matching `selector`.
void click_on(aogen_test::browser& b, const std::string& selector)
{
    const auto [x, y] = centre_of(b, selector);
    b.click(x, y);
}

} // namespace

TEST_CASE("page: report.html has no console error and one marker per timed variant in each panel")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    CHECK(b.errors().empty());
    for (const char* panel : {"default", "calibrated", "accumulated"}) {
        const auto shown = b.evaluate(std::string("Array.from(document.querySelectorAll('#plot .point[data-panel=\"") + panel +
                                      "\"]')).map(p => Number(p.dataset.variant))")
                               .get<std::vector<int>>();
        CHECK(std::set<int>(shown.begin(), shown.end()) == std::set<int>{0, 1, 2, 3, 5}); // 4 has no time
        CHECK(shown.size() == 5);
    }
    CHECK(b.evaluate("document.querySelectorAll('#variant-table tbody tr').length") == made_count);
    // The Pareto front's labels: each names a front variant, none collide.
    const json labels = b.evaluate("Array.from(document.querySelectorAll('#plot .label')).map(l => { const r = l.getBBox(); "
                                   "return [l.closest('.panel').dataset.panel, r.x, r.y, r.width, r.height]; })");
    CHECK(labels.size() >= 2);
    for (size_t i = 0; i < labels.size(); ++i)
        for (size_t k = i + 1; k < labels.size(); ++k) {
            if (labels[i][0] != labels[k][0]) continue;
            const double ax = labels[i][1], ay = labels[i][2], aw = labels[i][3], ah = labels[i][4];
            const double bx = labels[k][1], by = labels[k][2], bw = labels[k][3], bh = labels[k][4];
            CHECK_FALSE((ax < bx + bw && bx < ax + aw && ay < by + bh && by < ay + ah));
        }
}

TEST_CASE("page: hovering or focusing a marker names its variant, leaving it hides the name")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    for (int i : {0, 1, 2, 3, 5})
        for (const char* panel : {"default", "calibrated", "accumulated"}) {
            const auto [x, y] = centre_of(b, std::string("#plot .point[data-panel=\"") + panel + "\"][data-variant=\"" + std::to_string(i) + "\"]");
            b.mouse_move(x, y);
            INFO(made[i].name << " in the " << panel << " panel at " << x << ", " << y);
            CHECK(b.evaluate("document.getElementById('tooltip').hidden") == false);
            CHECK(b.evaluate("document.querySelector('#tooltip .name').textContent") == made[i].name);
            // Its errors, the one after the report's 8 frames among them.
            const std::string text = b.evaluate("document.getElementById('tooltip').textContent");
            CHECK(text.find(aogen_report::detail::fixed(0.9 * made[i].rmse, 4) + " after 8 frames") != std::string::npos);
            b.mouse_move(2, 2);
            CHECK(b.evaluate("document.getElementById('tooltip').hidden") == true);
        }
    // From the keyboard: a marker that takes the focus is named too, and Enter selects it.
    b.evaluate("document.querySelector('#plot .point[data-variant=\"2\"]').focus()");
    CHECK(b.evaluate("document.querySelector('#tooltip .name').textContent") == made[2].name);
    b.call("Input.dispatchKeyEvent", {{"type", "keyDown"}, {"key", "Enter"}, {"code", "Enter"}, {"windowsVirtualKeyCode", 13}});
    CHECK(b.evaluate("document.querySelector('#variant-table tr[aria-selected=\"true\"]').dataset.variant") == "2");
    b.evaluate("document.activeElement.blur()");
    CHECK(b.evaluate("document.getElementById('tooltip').hidden") == true);
    CHECK(b.errors().empty());
}

TEST_CASE("page: a column's button sorts the table both ways, missing values last")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    CHECK(row_order(b) == sorted_by(&made_variant::ms, true)); // as written: fastest first
    const std::string rmse_button = "#variant-table th:nth-child(11) button";
    REQUIRE(b.evaluate("document.querySelector('" + rmse_button + "').textContent") == "RMSE default");
    click_on(b, rmse_button);
    CHECK(row_order(b) == sorted_by(&made_variant::rmse, true));
    click_on(b, rmse_button);
    CHECK(row_order(b) == sorted_by(&made_variant::rmse, false));
    const std::string ms_button = "#variant-table th:nth-child(6) button"; // variant 4 has no time: last both ways
    REQUIRE(b.evaluate("document.querySelector('" + ms_button + "').textContent") == "ms");
    click_on(b, ms_button);
    CHECK(row_order(b) == sorted_by(&made_variant::ms, true));
    click_on(b, ms_button);
    CHECK(row_order(b) == sorted_by(&made_variant::ms, false));
    CHECK(b.errors().empty());
}

TEST_CASE("page: a filter hides the other rows and fades their markers")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    const auto choose = [&](const char* name, const char* value) {
        b.evaluate(std::string("(() => { const f = document.querySelector('#filters select[name=\"") + name + "\"]'); f.value = '" + value +
                   "'; f.dispatchEvent(new Event('change')); })()");
    };
    const auto faded = [&] {
        const auto v = b.evaluate("Array.from(document.querySelectorAll('#plot .point[data-panel=\"default\"].faded')).map(p => Number(p.dataset.variant))")
                           .get<std::vector<int>>();
        return std::set<int>(v.begin(), v.end());
    };
    choose("technique", "gtao");
    auto rows = row_order(b);
    CHECK(std::set<int>(rows.begin(), rows.end()) == std::set<int>{0, 4});
    CHECK(b.evaluate("document.getElementById('shown').textContent") == "2 of 6 variants shown");
    CHECK(faded() == std::set<int>{1, 2, 3, 5});
    choose("technique", "");
    choose("resolution", "full");
    rows = row_order(b);
    CHECK(std::set<int>(rows.begin(), rows.end()) == std::set<int>{3, 4, 5});
    choose("stage", "fragment");
    CHECK(row_order(b) == std::vector<int>{3});
    CHECK(faded() == std::set<int>{0, 1, 2, 5});
    CHECK(b.errors().empty());
}

TEST_CASE("page: selecting a row draws reference, variant and error on every scene")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    click_on(b, "#variant-table tbody tr[data-variant=\"1\"] td.name"); // a half-resolution variant
    // The images are decoded asynchronously: wait for them.
    CHECK(b.evaluate("new Promise(r => { const t = setInterval(() => { if (document.getElementById('strip-rows').dataset.variant === '1') "
                     "{ clearInterval(t); r(true); } }, 20); })") == true);
    CHECK(b.evaluate("document.querySelectorAll('#strip-rows figure').length") == 2);
    CHECK(b.evaluate("document.querySelectorAll('#strip-rows figure canvas').length") == 6);
    CHECK(b.evaluate("document.querySelector('#variant-table tr[aria-selected=\"true\"]').dataset.variant") == "1");
    CHECK(b.evaluate("document.querySelector('#plot .point.selected').dataset.variant") == "1");
    // Pixels: (x, y) = (5, 3) reads the half-resolution texel (2, 1) = 7 · (1 · 8 + 2) = 70;
    // its reference is round(5 / 16 · 255) = 80; the error panel is images.hpp's heat(70 − 80).
    const json px = b.evaluate("Array.from(document.querySelectorAll('#strip-rows figure')[0].querySelectorAll('canvas'))"
                               ".map(c => Array.from(c.getContext('2d').getImageData(5, 3, 1, 1).data))");
    const aogen_report::rgb heat = aogen_report::heat((70.0f - 80.0f) / 255.0f, aogen_report::heat_full_scale);
    CHECK(px[0] == json::array({80, 80, 80, 255}));
    CHECK(px[1] == json::array({70, 70, 70, 255}));
    CHECK(px[2] == json::array({heat[0], heat[1], heat[2], 255}));
    // A background pixel (column 0) is blue-grey in every panel.
    const json bg = b.evaluate("Array.from(document.querySelectorAll('#strip-rows figure')[0].querySelectorAll('canvas'))"
                               ".map(c => Array.from(c.getContext('2d').getImageData(0, 3, 1, 1).data))");
    const aogen_report::rgb blue = aogen_report::background_colour;
    for (const json& p : bg) CHECK(p == json::array({blue[0], blue[1], blue[2], 255}));
    CHECK(b.errors().empty());
}

TEST_CASE("page: a scene wider than the page's images is shown box-filtered down by a whole factor")
{
    // 1000 × 6 at most 480 wide: a factor of 3, shown 334 × 2; each shown pixel the mean of
    // its 3 × 3 block's valid pixels (column 0 is background).
    aogen_report::report_data d = small_report();
    d.scenes = {scene_of("wide", 1000, 6)};
    for (aogen_report::variant_record& v : d.variants) {
        v.runs.resize(1);
        aogen_report::ao_readback& ao = v.runs[0].ao;
        ao.width = 1000 / ao.factor, ao.height = 6 / ao.factor;
        ao.unorm.clear();
        for (int i = 0; i < ao.width * ao.height; ++i) ao.unorm.push_back(uint8_t(i * 7 % 256));
    }
    const auto block_mean = [&](int x, int y, const std::function<double(int, int)>& at) {
        double sum = 0;
        int count = 0;
        for (int sy = 3 * y; sy < 3 * y + 3; ++sy)
            for (int sx = std::max(1, 3 * x); sx < 3 * x + 3; ++sx) sum += at(sx, sy), ++count;
        return int(std::lround(sum / count * 255));
    };
    const aogen_report::ao_readback& half = d.variants[1].runs[0].ao; // 500 × 3, nearest-upsampled
    const int reference = block_mean(200, 1, [](int sx, int) { return sx / 1000.0; });
    const int ao = block_mean(200, 1, [&](int sx, int sy) { return half.unorm[size_t(sy / 2) * 500 + sx / 2] / 255.0; });
    opened_page page(aogen_report::report_page(d, {"aogen_report", true}));
    click_on(page.b, "#variant-table tbody tr[data-variant=\"1\"] td.name");
    CHECK(page.b.evaluate("new Promise(r => { const t = setInterval(() => { if (document.getElementById('strip-rows').dataset.variant === '1') "
                          "{ clearInterval(t); r(true); } }, 20); })") == true);
    const json canvases = page.b.evaluate("Array.from(document.querySelectorAll('#strip-rows canvas')).map(c => "
                                          "[c.width, c.height, Array.from(c.getContext('2d').getImageData(200, 1, 1, 1).data)])");
    REQUIRE(canvases.size() == 3);
    for (const json& c : canvases) CHECK((c[0] == 334 && c[1] == 2));
    CHECK(canvases[0][2] == json::array({reference, reference, reference, 255}));
    CHECK(canvases[1][2] == json::array({ao, ao, ao, 255}));
    CHECK(page.b.errors().empty());
}

TEST_CASE("page: user text is shown as text, never run")
{
    opened_report page;
    aogen_test::browser& b = page.b;
    CHECK(b.evaluate("typeof window.injected") == "undefined");
    CHECK(b.evaluate("document.querySelector('#scenes table').textContent.includes(" + json(script_scene).dump() + ")") == true);
    CHECK(b.evaluate("document.querySelector('.facts').textContent.includes('a <b>device</b> & co')") == true);
    CHECK(b.evaluate("document.querySelectorAll('script').length") == 2); // the data and the page's own
    CHECK(b.errors().empty());
}

TEST_CASE("page: the stability suite's page shows every run and names each failure's figure")
{
    aogen_report::suite_data d;
    d.device = "lavapipe";
    d.grid = 32;
    d.variants = {"gtao-2x2-half-denoise-gbufworld-std-persp-cs", "ssao-s16-half-bilateral-gbufworld-std-persp-cs"};
    for (const char* name : {"grazing_floor", "<img src=x onerror=\"window.injected=1\">"}) {
        aogen_report::suite_case_record c;
        c.c.name = name, c.c.about = "a case";
        for (const std::string& v : d.variants) {
            aogen_report::suite_run r;
            r.variant = v, r.pass = true, r.decided_by = "RMSE 0.05 ≤ 0.08", r.rmse = 0.05, r.error_limit = 0.08;
            c.runs.push_back(r);
        }
        d.cases.push_back(c);
    }
    d.cases[1].runs[1].pass = false, d.cases[1].runs[1].decided_by = "background pixel (3, 4) is 0.5, not 1";
    d.cases[0].runs[0].skipped = "planted: cannot run";
    scratch s;
    aogen::tools::write_file(s.dir / "report.html", aogen_report::suite_page(d, "aogen_report --suite stability"));
    aogen_test::browser b(chromium());
    b.open("file://" + (s.dir / "report.html").string()); // no script to wait for
    CHECK(b.errors().empty());
    CHECK(b.evaluate("typeof window.injected") == "undefined");
    CHECK(b.evaluate("Array.from(document.querySelectorAll('.suite-grid tbody td')).map(c => c.className)") ==
          json::array({"", "skip", "pass", "num", "", "pass", "fail", "num"}));
    CHECK(b.evaluate("document.querySelector('.suite-grid td.fail').title").get<std::string>().find("background pixel (3, 4) is 0.5") != std::string::npos);
    CHECK(b.evaluate("document.querySelector('#failures').textContent").get<std::string>().find("background pixel (3, 4) is 0.5") != std::string::npos);
    CHECK(b.evaluate("document.querySelector('#cases table').textContent.includes('<img src=x')") == true);
}

// A report aogen_report made (report_test.sh): no console error, a marker per variant with a
// time, and every scene's images for the fastest variant.
TEST_CASE("page: a report made by aogen_report", "[.]")
{
    const char* page = std::getenv("AOGEN_PAGE");
    REQUIRE(page != nullptr); // set by report_test.sh; never a silent pass
    const json results = json::parse(aogen::tools::read_file((fs::path(page).parent_path() / "results.json").string()));
    size_t timed = 0;
    for (const json& v : results["variants"]) timed += v["ms"].is_number() && v["rmse"].is_number();
    REQUIRE(timed > 0);
    aogen_test::browser b(chromium());
    open_page(b, fs::absolute(page));
    CHECK(b.errors().empty());
    CHECK(b.evaluate("document.querySelectorAll('#plot .point[data-panel=\"default\"]').length") == timed);
    CHECK(b.evaluate("document.querySelectorAll('#variant-table tbody tr').length") == results["variants"].size());
    const auto [x, y] = centre_of(b, "#plot .point[data-panel=\"default\"]");
    b.mouse_move(x, y);
    const std::string first = b.evaluate("document.querySelector('#plot .point[data-panel=\"default\"]').dataset.variant");
    CHECK(b.evaluate("document.querySelector('#tooltip .name').textContent") == results["variants"][std::stoi(first)]["name"]);
    click_on(b, "#variant-table tbody tr td.name");
    CHECK(b.evaluate("new Promise(r => { const t = setInterval(() => { if (document.getElementById('strip-rows').dataset.variant) "
                     "{ clearInterval(t); r(document.querySelectorAll('#strip-rows figure').length); } }, 20); })") == results["scenes"].size());
    CHECK(b.errors().empty());
    // The plot alone, as report.md shows it: well-formed SVG with the same markers.
    b.open("file://" + (fs::absolute(page).parent_path() / "error_vs_time.svg").string());
    CHECK(b.evaluate("document.querySelectorAll('parsererror').length") == 0);
    CHECK(b.evaluate("document.querySelectorAll('.point[data-panel=\"default\"]').length") == timed);
    CHECK(b.errors().empty());
}

// A stability suite's page aogen_report made (report_test.sh's suite case): no console error,
// a grid row per variant and a cell per case, as many failed cells as results.json's failures.
TEST_CASE("page: a stability suite page made by aogen_report", "[.]")
{
    const char* page = std::getenv("AOGEN_PAGE");
    REQUIRE(page != nullptr); // set by report_test.sh; never a silent pass
    const json results = json::parse(aogen::tools::read_file((fs::path(page).parent_path() / "results.json").string()));
    REQUIRE(!results["cases"].empty());
    aogen_test::browser b(chromium());
    b.open("file://" + fs::absolute(page).string());
    CHECK(b.errors().empty());
    const size_t variants = results["cases"][0]["runs"].size(), cases = results["cases"].size();
    CHECK(b.evaluate("document.querySelectorAll('.suite-grid tbody tr').length") == variants);
    CHECK(b.evaluate("document.querySelectorAll('.suite-grid tbody td.pass, .suite-grid tbody td.fail, .suite-grid tbody td.skip').length") ==
          variants * cases);
    CHECK(b.evaluate("document.querySelectorAll('.suite-grid tbody td.fail').length") == results["failures"]);
}

// docs/report_page.png: a real report at 1280 × 800 with the fastest Pareto variant selected
// and a marker hovered (AOGEN_PAGE: its report.html, AOGEN_PAGE_SCREENSHOT: the PNG to write).
TEST_CASE("page: screenshot", "[.]")
{
    const char *page = std::getenv("AOGEN_PAGE"), *out = std::getenv("AOGEN_PAGE_SCREENSHOT");
    REQUIRE(page != nullptr);
    REQUIRE(out != nullptr);
    aogen_test::browser b(chromium());
    b.call("Emulation.setDeviceMetricsOverride", {{"width", 1280}, {"height", 800}, {"deviceScaleFactor", 1}, {"mobile", false}});
    open_page(b, fs::absolute(page));
    const std::string hovered = b.evaluate("(() => { const front = Array.from(document.querySelectorAll('#plot .label')); "
                                           "return front.length ? front[0].dataset.variant : '0'; })()");
    b.evaluate("document.getElementById('plot').scrollIntoView()");
    const json at = b.evaluate("(() => { const r = document.querySelector('#plot .point[data-panel=\"default\"][data-variant=\"" + hovered +
                               "\"]').getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()");
    b.mouse_move(at[0].get<double>(), at[1].get<double>());
    aogen::tools::write_file(out, b.screenshot(1280, 800));
    CHECK(b.errors().empty());
}

// A crowded front, as the default report's is between 2 and 5 ms: forty Pareto-optimal
// variants a few per cent apart. Measured by the browser's own text layout (getBBox), no two
// labels overlap, no label covers a marker, and every label lies inside its panel.
TEST_CASE("page: the plot's labels collide with nothing on a crowded front")
{
    std::vector<aogen_report::plot_point> points;
    for (size_t i = 0; i < 40; ++i) {
        const double ms = 2.0 * std::pow(1.025, double(i)), error = 0.09 - 0.0008 * double(i);
        const std::string name = "gtao-" + std::to_string(i % 4 + 1) + "x" + std::to_string(i / 4 + 1) + "-half-denoise-gbufworld-std-persp-cs";
        points.push_back({i, name, aogen_report::plot_label(name), "gtao", "compute", ms, ms * 0.95, ms * 1.05, error, error, error, true, true, true});
    }
    scratch s;
    aogen::tools::write_file(s.dir / "plot.svg", aogen_report::error_time_svg(points, "crowded"));
    aogen_test::browser b(chromium());
    b.open("file://" + (s.dir / "plot.svg").string());
    CHECK(b.errors().empty());
    CHECK(b.evaluate("document.querySelectorAll('parsererror').length") == 0); // well-formed XML
    CHECK(b.evaluate("document.querySelectorAll('.point').length") == 80);
    const json boxes = b.evaluate(R"((() => {
        const box = (e) => { const r = e.getBBox(); return [r.x, r.y, r.x + r.width, r.y + r.height]; };
        return Array.from(document.querySelectorAll('.panel')).map(panel => ({
            frame: box(panel.querySelector('rect')),
            labels: Array.from(panel.querySelectorAll('.label')).map(box),
            points: Array.from(panel.querySelectorAll('.point')).map(box)}));
    })())");
    for (const json& panel : boxes) {
        const auto overlap = [](const json& a, const json& c) {
            return a[0].get<double>() < c[2].get<double>() && c[0].get<double>() < a[2].get<double>() && a[1].get<double>() < c[3].get<double>() &&
                   c[1].get<double>() < a[3].get<double>();
        };
        const json& labels = panel["labels"];
        CHECK(labels.size() >= 5); // some are placed, not none
        CHECK(labels.size() < 40); // and a crowded front does not get them all
        for (size_t i = 0; i < labels.size(); ++i) {
            CHECK(labels[i][0] >= panel["frame"][0]);
            CHECK(labels[i][2] <= panel["frame"][2]);
            CHECK(labels[i][1] >= panel["frame"][1]);
            CHECK(labels[i][3] <= panel["frame"][3]);
            for (size_t k = i + 1; k < labels.size(); ++k) CHECK_FALSE(overlap(labels[i], labels[k]));
            for (const json& p : panel["points"]) CHECK_FALSE(overlap(labels[i], p));
        }
    }
}
