// Kind selection, synchronised moves of any kind, and the sampler.
#include "motion/message_print.h"
#include "motion/any_profile.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion;

TEST(AnyProfile, KindsByNameAndMissingFieldsNamed)
{
    for (ProfileKind k : {ProfileKind::SeedSCurve, ProfileKind::Trapezoid, ProfileKind::Exponential, ProfileKind::JerkLimited})
        EXPECT_EQ(profileKindFromName(profileKindName(k)), k);
    EXPECT_FALSE(profileKindFromName("s-curve"));
    ProfileRequest r;
    r.kind = ProfileKind::JerkLimited;
    r.vMaxMmS = 100;
    r.aMaxMmS2 = 1000;
    EXPECT_EQ(motion::msg::debugString(planProfile(10, r).error()), "profile.not_positive{field=\"jMaxMmS3\", value=0, kind=\"jerk-limited\"}");
    r.kind = ProfileKind::SeedSCurve;
    EXPECT_EQ(motion::msg::debugString(planProfile(10, r).error()), "profile.not_positive{field=\"accelTimeS\", value=0, kind=\"seed-scurve\"}");
    r.kind = ProfileKind::Trapezoid;
    r.plateauMm = 1;
    EXPECT_EQ(motion::msg::debugString(planProfile(10, r).error()),
              "profile.start_speed_for_plateau{field=\"startSpeedMmS\", value=0, kind=\"trapezoid\"}");
}

TEST(AnyProfile, EveryKindLandsOnItsDistance)
{
    ProfileRequest r;
    r.vMaxMmS = 50;
    r.aMaxMmS2 = 500;
    r.jMaxMmS3 = 5000;
    r.accelTimeS = 0.2;
    r.startSpeedMmS = 2;
    r.plateauMm = 0.1;
    for (ProfileKind k : {ProfileKind::SeedSCurve, ProfileKind::Trapezoid, ProfileKind::Exponential, ProfileKind::JerkLimited}) {
        r.kind = k;
        const auto p = planProfile(-25, r);
        ASSERT_TRUE(p) << p.error();
        EXPECT_EQ(p->kind(), k);
        EXPECT_EQ(p->at(p->duration()).s, -25) << profileKindName(k);
        const auto samples = sampleProfile(*p, 0.01);
        ASSERT_GE(samples.size(), 2u);
        EXPECT_EQ(samples.front().t, 0);
        EXPECT_EQ(samples.back().t, p->duration());
        for (const auto& s : samples)
            EXPECT_LE(std::fabs(s.v), 50 * (1 + 1e-12)) << profileKindName(k);
    }
}

TEST(AnyProfile, SynchronizedSeedMoveReproducesTable2Timing)
{
    // Same limits on both axes (x's 37.5 mm/s): the longer y axis (40 mm) sets the pace.
    ProfileRequest r;
    r.kind = ProfileKind::SeedSCurve;
    r.vMaxMmS = 37.5;
    r.accelTimeS = 0.1;
    const double target[] = {30, 40};
    const auto move = planSynchronized(target, 2, r);
    ASSERT_TRUE(move) << move.error();
    EXPECT_NEAR(move->axisAt(1, 0.5).v, 37.5, 1e-9);
    EXPECT_NEAR(move->axisAt(0, 0.5).v, 37.5 * 0.75, 1e-9);
    EXPECT_NEAR(move->duration(), 0.1 + 40 / 37.5, 1e-12);
    EXPECT_EQ(move->axisAt(0, move->duration()).s, 30);
}

TEST(AnyProfile, SamplerRefusesRunawayRequests)
{
    const auto p = JerkLimitedProfile::plan(1000, {1, 1, 1});
    ASSERT_TRUE(p);
    EXPECT_TRUE(sampleProfile(*p, 1e-9).empty());
    EXPECT_TRUE(sampleProfile(*p, 0).empty());
    EXPECT_FALSE(sampleProfile(*p, 1).empty());
}
