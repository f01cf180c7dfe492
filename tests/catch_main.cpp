// The one Catch2 main shared by every test executable. Every test case must assert something:
// one that runs no assertion fails (Catch's NoAssertions warning, on whatever the command line
// says), so a test that returns early without a check cannot pass unseen. A deliberate skip
// (support.hpp's skip_missing_dependency under AOGEN_TESTS_OPTIONAL_DEPS=1) says so with an
// explicit SUCCEED.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[])
{
    Catch::Session session;
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
    Catch::ConfigData& config = session.configData();
    config.warnings = static_cast<Catch::WarnAbout::What>(config.warnings | Catch::WarnAbout::NoAssertions);
    session.useConfigData(config);
    return session.run();
}
