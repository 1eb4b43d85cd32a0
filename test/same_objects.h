// Comparing scenes read in two ways (text, octrees frozen by Radiance or Brume).
#pragma once
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.h"

namespace brume_test {

// Same objects; frozen octrees store reals with a 31-bit mantissa.
inline void expectSameObjects(const brume::Scene& actual, const brume::Scene& expected) {
    ASSERT_EQ(actual.objects.size(), expected.objects.size());
    for (size_t i = 0; i < actual.objects.size(); ++i) {
        const brume::SceneObject &a = actual.objects[i], &e = expected.objects[i];
        SCOPED_TRACE(e.name);
        EXPECT_EQ(a.type, e.type);
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.modifier, e.modifier);
        EXPECT_EQ(a.strings, e.strings);
        EXPECT_EQ(a.integers, e.integers);
        ASSERT_EQ(a.reals.size(), e.reals.size());
        for (size_t j = 0; j < a.reals.size(); ++j) EXPECT_NEAR(a.reals[j], e.reals[j], 1e-9 * std::abs(e.reals[j]));
    }
    EXPECT_EQ(actual.lastDefinition, expected.lastDefinition);
}

}  // namespace brume_test
