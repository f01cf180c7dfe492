// aogen_report/suite_page.hpp — the stability suite's report.html: one self-contained page.
//
//     std::string html = aogen_report::suite_page(d, command);
//
// The same sections as its report.md (suite_report.hpp writes the words once): the facts
// and how to read them; the cases with their criteria and the run closest to its limit;
// the grid of variants × cases, each cell ✓, ✗ or – and, on hover, the figure that decided
// it (the cell's title); every failure with its figure; what could not run. No script:
// the page is tables. Every text a user wrote (case names from case files, the command)
// is HTML-escaped.
#pragma once

#include "html_text.hpp"
#include "page_assets.hpp"
#include "suite_report.hpp"
#include "text_table.hpp"

#include <sstream>

namespace aogen_report {

inline std::string suite_page(const suite_data& d, const std::string& command)
{
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>aogen stability suite — " << html_escape(d.device)
         << "</title>\n<style>" << page_style << "</style>\n</head>\n<body>\n<header>\n<h1>aogen stability suite</h1>\n"
         << html_list(suite_facts(d, command), "class=\"facts\"");
    html << "<p class=\"how\">" << html_from_markdown(suite_how_to_read()) << "</p>\n</header>\n";

    html << "<section id=\"cases\">\n<h2>Cases</h2>\n<p>Each case's run closest to its error limit, with the figure that decided it "
            "(every run's is in results.json).</p>\n" << html_table(suite_cases_table(d)) << "</section>\n";

    html << "<section id=\"grid\">\n<h2>Variants × cases</h2>\n<p>✓ passed, ✗ failed, – could not run; hover a cell for the "
            "figure that decided it. Columns: the cases' numbers above.</p>\n<div class=\"table-scroll\"><table class=\"suite-grid\">\n"
            "<thead><tr><th>variant</th>";
    for (size_t i = 0; i < d.cases.size(); ++i) html << "<th class=\"mid\" title=\"" << html_escape(d.cases[i].c.name) << "\">" << i + 1 << "</th>";
    html << "<th class=\"num\">failed</th></tr></thead>\n<tbody>\n";
    for (size_t v = 0; v < d.variants.size(); ++v) {
        size_t failed = 0;
        html << "<tr><td><code>" << html_escape(d.variants[v]) << "</code></td>";
        for (const suite_case_record& c : d.cases) {
            const suite_run& r = c.runs[v];
            const char* cls = !r.ran() ? "skip" : r.pass ? "pass" : "fail";
            html << "<td class=\"" << cls << "\" title=\"" << html_escape(c.c.name + ": " + (r.ran() ? r.decided_by : r.skipped)) << "\">"
                 << (!r.ran() ? "–" : r.pass ? "✓" : "✗") << "</td>";
            failed += r.ran() && !r.pass;
        }
        html << "<td class=\"num\">" << failed << "</td></tr>\n";
    }
    html << "</tbody>\n</table></div>\n</section>\n";

    html << "<section id=\"failures\">\n<h2>Failures</h2>\n";
    const std::vector<std::string> failures = suite_failure_lines(d);
    html << (failures.empty() ? "<p>None.</p>\n" : html_list(failures, "class=\"summary-fail\""));
    html << "</section>\n";
    const std::vector<std::string> not_run = suite_not_run_lines(d);
    if (!not_run.empty()) html << "<section id=\"not-run\">\n<h2>Not run</h2>\n" << html_list(not_run) << "</section>\n";
    html << "</body>\n</html>\n";
    return html.str();
}

} // namespace aogen_report
