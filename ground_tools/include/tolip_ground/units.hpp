// The deck's and the reports' units that are not the core's (the core works in ft, s, slug, lbf,
// rad: tolip/core/constants.hpp has the degree). Conversions happen at the edges, with these.
#pragma once

namespace tolip::ground {

// The deck's inch (body stations, moment arms, c.g. histories) in ft.
inline constexpr double kFeetPerInch = 1.0 / 12.0;

// The international nautical mile (1852 m) in ft: the unit of the orbit summary's altitudes (data
// block 19's 300 n.mi. orbit is 1,822,834.647 ft), of downrange in the plots and of the bench's
// tracking limits.
inline constexpr double kFeetPerNauticalMile = 1852.0 / 0.3048;

}  // namespace tolip::ground
