// aogen/techniques.hpp — the table of AO techniques: one row each, and nothing per technique elsewhere.
//
// WHAT
//   technique_table      the rows (techniques/descriptor.hpp's technique_desc), in the order
//                        of axes.hpp's technique enumeration: SSAO, GTAO, VBAO, SAO
//   technique_of(t)      the row of technique `t`
//
//   The plan (plan.hpp), a chain's inputs (chain_inputs.hpp), the frame index (temporal.hpp)
//   and the selection (selection.hpp) ask the row; none of them tests which technique a
//   variant has.
//
// USAGE
//     #include <aogen/techniques.hpp>
//     aogen::technique_of(aogen::technique::gtao).files(v);   // {"common/slices.glsl", "gtao.glsl"}
//
// ERRORS
//   technique_of: aogen::error for a value outside the enumeration. A row left out of the
//   table, out of order, or with a member unset does not compile (the static_asserts below;
//   tests/techniques/ plants each).
//
// WHY
//   A technique used to be a value tested in `if` chains across some twenty files, three of
//   which fell back to SSAO without a word. Here a new technique is one header under
//   techniques/ and one row below, and the compiler names every part it has not written.
#pragma once

#include "axes.hpp"
#include "names.hpp"
#include <aogen/techniques/descriptor.hpp>
#include <aogen/techniques/gtao.hpp>
#include <aogen/techniques/sao.hpp>
#include <aogen/techniques/ssao.hpp>
#include <aogen/techniques/vbao.hpp>

#include <array>
#include <cstddef>

namespace aogen {

inline constexpr std::array<technique_desc, technique_names.size()> technique_table{{
    techniques::ssao,
    techniques::gtao,
    techniques::vbao,
    techniques::sao,
}};

namespace detail {

// Row i is technique i, with every member set: a row the table does not have is a
// value-initialised one, so this fails for a row left out as for one left half-written.
constexpr bool technique_table_complete()
{
    for (std::size_t i = 0; i < technique_table.size(); ++i) {
        const technique_desc& t = technique_table[i];
        if (t.id != technique_names[i].value) return false;
        if (!t.block || !t.pack || !t.noise_size || !t.files || !t.defines || !t.constants || !t.period_turns || !t.counts_text ||
            t.taps_per_iteration < 1)
            return false;
    }
    return true;
}

} // namespace detail

static_assert(detail::technique_table_complete(),
              "technique_table: every technique of technique_names needs its row, in the enumeration's order, with every member set");

// The row of technique `t`.
inline const technique_desc& technique_of(technique t)
{
    names::require_listed(technique_names, t, "technique");
    return technique_table[static_cast<std::size_t>(t)];
}

} // namespace aogen
