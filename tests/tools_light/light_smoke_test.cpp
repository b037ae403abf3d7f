#include <gtest/gtest.h>
TEST(LightSmoke, Placeholder) {}
