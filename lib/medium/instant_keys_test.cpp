// InstantKeys: where the smoke changes in time each instant keeps its own state and moving on forgets the others';
// where nothing changes, every instant shares one and nothing is forgotten.
#include "medium/instant_keys.h"

#include <gtest/gtest.h>

using brume::InstantKeys;

TEST(InstantKeys, EachInstantItsOwnOnlyWhereTheSmokeChanges) {
    InstantKeys timed(true), still(false);
    EXPECT_EQ(timed.of(60), 60);
    EXPECT_NE(timed.of(60), timed.of(120));
    EXPECT_TRUE(timed.keptAt(timed.of(120), 120));
    EXPECT_FALSE(timed.keptAt(timed.of(60), 120));
    EXPECT_EQ(still.of(60), still.of(120));
    EXPECT_TRUE(still.keptAt(still.of(60), 120));
}
