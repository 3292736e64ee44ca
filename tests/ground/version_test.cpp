#include <gtest/gtest.h>

#include <cstring>

#include "tolip_ground/version.hpp"

TEST(GroundVersion, IsNonEmpty) { EXPECT_GT(std::strlen(tolip::ground::version_string()), 0u); }
