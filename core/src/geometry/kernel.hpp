// The one geometric kernel of the project: exact predicates, inexact constructions.
#pragma once
// The build defines CGAL_ALWAYS_ROUND_TO_NEAREST (wasm cannot change the rounding
// mode) and CGAL_DISABLE_GMP (no GMP in wasm) for native and wasm alike, so both
// compute the same thing.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace hodt {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;
}  // namespace hodt
