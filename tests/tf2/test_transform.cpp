#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/Transform.hpp"

using namespace tf2test;
using ros2vtk::tf2::interpolate;

TEST(Transform, AppliesRotationThenTranslation)
{
  // 90 deg about z maps x to y; then shift by (1, 2, 3).
  const Transform t = make_transform({ 1, 2, 3 }, about(0, 0, 1, 90));
  EXPECT_TRUE(same_vector(t.apply({ 1, 0, 0 }), { 1, 3, 3 }));
  EXPECT_TRUE(same_vector(t.apply({ 0, 1, 0 }), { 0, 2, 3 }));
}

TEST(Transform, ComposeAppliesRightOperandFirst)
{
  // b: C -> B, translation (1, 0, 0). a: B -> A, 90 deg about z.
  const Transform a = make_transform({ 0, 0, 0 }, about(0, 0, 1, 90));
  const Transform b = make_transform({ 1, 0, 0 });
  const Transform ab = a * b;
  // Origin of C: (1,0,0) in B, rotated into A: (0,1,0).
  EXPECT_TRUE(same_vector(ab.translation, { 0, 1, 0 }));
  EXPECT_TRUE(same_rotation(ab.rotation, about(0, 0, 1, 90)));
  // Point (0,0,5) of C: (1,0,5) in B, (0,1,5) in A.
  EXPECT_TRUE(same_vector(ab.apply({ 0, 0, 5 }), { 0, 1, 5 }));
}

TEST(Transform, InverseUndoes)
{
  const Transform t = make_transform({ 1, 2, 3 }, about(0, 0, 1, 90));
  const Transform inv = t.inverse();
  // By hand: R^-1 = -90 deg about z, maps (x, y) to (y, -x); translation -R^-1 t = -(2, -1, 3).
  EXPECT_TRUE(same_vector(inv.translation, { -2, 1, -3 }));
  EXPECT_TRUE(same_rotation(inv.rotation, about(0, 0, 1, -90)));
  EXPECT_TRUE(same_vector(inv.apply(t.apply({ 4, 5, 6 })), { 4, 5, 6 }));
}

TEST(Transform, IsometryRoundTrip)
{
  const Transform t = make_transform({ 0.5, -1, 2 }, about(1, 0, 0, 30));
  const Eigen::Isometry3d iso = t.to_isometry();
  EXPECT_TRUE(same_vector(
    iso * Eigen::Vector3d(0, 1, 0), { 0.5, -1 + std::cos(kPi / 6), 2 + std::sin(kPi / 6) }));
  const Transform back = Transform::from_isometry(iso);
  EXPECT_TRUE(same_vector(back.translation, t.translation));
  EXPECT_TRUE(same_rotation(back.rotation, t.rotation));
}

TEST(Transform, InterpolatesTranslationLinearly)
{
  const Transform a = make_transform({ 0, 0, 0 });
  const Transform b = make_transform({ 2, 4, -6 });
  EXPECT_TRUE(same_vector(interpolate(a, b, 0.5).translation, { 1, 2, -3 }));
  EXPECT_TRUE(same_vector(interpolate(a, b, 0.25).translation, { 0.5, 1, -1.5 }));
  EXPECT_TRUE(same_vector(interpolate(a, b, 0.0).translation, { 0, 0, 0 }));
  EXPECT_TRUE(same_vector(interpolate(a, b, 1.0).translation, { 2, 4, -6 }));
}

TEST(Transform, SlerpOfKnownRotation)
{
  // Identity to 90 deg about z: halfway is 45 deg, a quarter is 22.5 deg.
  const Transform a = make_transform({ 0, 0, 0 });
  const Transform b = make_transform({ 0, 0, 0 }, about(0, 0, 1, 90));
  const Eigen::Quaterniond half = interpolate(a, b, 0.5).rotation;
  EXPECT_NEAR(half.z(), std::sin(kPi / 8), 1e-12);
  EXPECT_NEAR(half.w(), std::cos(kPi / 8), 1e-12);
  EXPECT_NEAR(half.x(), 0.0, 1e-12);
  EXPECT_TRUE(same_rotation(interpolate(a, b, 0.25).rotation,
    Eigen::Quaterniond(std::cos(kPi / 16), 0, 0, std::sin(kPi / 16))));
}

TEST(Transform, SlerpTakesTheShortPath)
{
  // The same 90 deg rotation written as -q: a long-path slerp would pass through 135 deg about
  // the other way; the short path still goes through +45 deg about z.
  const Transform a = make_transform({ 0, 0, 0 });
  const Eigen::Quaterniond q = about(0, 0, 1, 90);
  const Transform b =
    make_transform({ 0, 0, 0 }, Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()));
  const Transform mid = interpolate(a, b, 0.5);
  EXPECT_TRUE(same_vector(mid.apply({ 1, 0, 0 }), { std::sqrt(0.5), std::sqrt(0.5), 0 }));
}
