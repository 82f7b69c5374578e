#include "datasets/synth/scene.h"

#include <gtest/gtest.h>

#include "datasets/synth/counter_rng.h"
#include "datasets/synth/multi_room_layouts.h"
#include "datasets/synth/room_layout.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

using Eigen::Vector3d;

TEST(SyntheticScene, RaysHitTheAnalyticSurfaces) {
  const SyntheticScene& scene = test::shared_room();
  // Straight down from above the desk: its top at z = 0.76.
  auto hit = scene.cast_ray(Vector3d(0.1, -0.3, 2.0), Vector3d(0, 0, -2));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, (2.0 - 0.76) / 2, 1e-12);  // t in units of the direction given
  EXPECT_NEAR(hit->point.z(), 0.76, 1e-12);
  EXPECT_EQ(hit->normal, Vector3d(0, 0, 1));
  // Up: the ceiling, 2.7 m; towards -x at head height: the plain west wall at x = -2.5.
  hit = scene.cast_ray(Vector3d(1.0, -1.0, 1.5), Vector3d(0, 0, 1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.z(), 2.7, 1e-12);
  EXPECT_EQ(hit->normal, Vector3d(0, 0, -1));
  hit = scene.cast_ray(Vector3d(1.0, -1.0, 1.5), Vector3d(-1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), -2.5, 1e-12);
  EXPECT_EQ(hit->normal, Vector3d(1, 0, 0));
  // The plain pillar stands 0.3 m proud of that wall.
  hit = scene.cast_ray(Vector3d(0, 0, 1.5), Vector3d(-1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), -2.2, 1e-12);
}

TEST(SyntheticScene, DistancesAreExact) {
  const SyntheticScene& scene = test::shared_room();
  // Above the desk's free corner: nearest is the desk top, 0.24 m down.
  EXPECT_NEAR(scene.signed_distance(Vector3d(-0.65, 0.35, 1.0)), 0.24, 1e-12);
  // Inside the tall cabinet (x 2.05..2.5): 5 cm from its front face.
  EXPECT_NEAR(scene.signed_distance(Vector3d(2.1, -1.5, 1.0)), -0.05, 1e-12);
  EXPECT_NEAR(scene.distance_to_surface(Vector3d(2.1, -1.5, 1.0)), 0.05, 1e-12);
  // Beyond the west wall.
  EXPECT_NEAR(scene.signed_distance(Vector3d(-2.6, -1.0, 1.5)), -0.1, 1e-12);
  // Every hit lies on a surface.
  CounterRng rng(5, 0, 0);
  for (int i = 0; i < 1000; ++i) {
    const Vector3d origin(rng.uniform(-1.8, 1.8), rng.uniform(-1.4, 1.4), rng.uniform(1.3, 2.5));
    const Vector3d direction(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const auto hit = scene.cast_ray(origin, direction);
    ASSERT_TRUE(hit);
    EXPECT_LT(scene.distance_to_surface(hit->point), 1e-9);
    EXPECT_GE(scene.signed_distance(origin + 0.5 * hit->t * direction), 0.0);
  }
}

TEST(SyntheticScene, ConeCullingNeverChangesAHit) {
  const SyntheticScene& scene = test::shared_room();
  CounterRng rng(6, 0, 0);
  for (int cone = 0; cone < 200; ++cone) {
    const Vector3d origin(rng.uniform(-1.8, 1.8), rng.uniform(-1.4, 1.4), rng.uniform(0.9, 2.5));
    const Vector3d axis(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 0.3));
    const Vector3d a = axis.unitOrthogonal(), b = axis.cross(a).normalized();
    const double half = axis.norm() * rng.uniform(0.01, 0.3);
    const std::array<Vector3d, 4> edges = {axis - half * a - half * b, axis + half * a - half * b,
                                           axis + half * a + half * b, axis - half * a + half * b};
    const std::vector<int> parts = scene.parts_in_cone(origin, edges);
    for (int i = 0; i < 50; ++i) {
      const Vector3d d = axis + half * rng.uniform(-1, 1) * a + half * rng.uniform(-1, 1) * b;
      const auto culled = scene.cast_ray(origin, d, parts), full = scene.cast_ray(origin, d);
      ASSERT_TRUE(culled && full);
      EXPECT_EQ(culled->t, full->t);
      EXPECT_EQ(culled->surface, full->surface);
    }
  }
}

TEST(SyntheticScene, PlainSurfacesAreUniformTexturedOnesAreNot) {
  const SyntheticScene& scene = test::shared_room();
  const auto spread = [&](const Vector3d& origin, const Vector3d& axis, const Vector3d& across) {
    double lo = 1e9, hi = -1e9;
    for (int i = -20; i <= 20; ++i) {
      const auto hit = scene.cast_ray(origin, axis + 0.01 * i * across);
      const Eigen::Vector3f albedo_lit = scene.colour(*hit, 0.002);
      lo = std::min<double>(lo, albedo_lit.mean());
      hi = std::max<double>(hi, albedo_lit.mean());
    }
    return hi - lo;
  };
  // Along the plain west wall (lighting varies only slowly) and the textured south wall.
  EXPECT_LT(spread(Vector3d(-1.5, -1.0, 1.5), Vector3d(-1, 0, 0), Vector3d(0, 1, 0)), 6.0);
  EXPECT_GT(spread(Vector3d(0.0, -1.0, 1.5), Vector3d(0, -1, 0), Vector3d(1, 0, 0)), 40.0);
}

TEST(SyntheticScene, TwinPiecesAndTheirLightsRepeatTheSameColours) {
  const SyntheticScene& scene = test::shared_scene(Preset::kLookalike);
  CounterRng rng(8, 0, 0);
  for (int i = 0; i < 200; ++i) {
    // Rays from the west room's middle, and the same rays one twin offset east, towards the
    // rooms' own walls and floor (not the end walls, the doorway or the shared ceiling).
    const Vector3d origin = kFirstTwinCentre + Vector3d(rng.uniform(-1, 1), -1.2, 1.4);
    const double north_or_south = rng.uniform(0, 1) < 0.5 ? -1 : 1;
    const Vector3d direction(rng.uniform(-0.2, 0.2), north_or_south * rng.uniform(0.5, 1),
                             rng.uniform(-1, 0.1));
    const auto west = scene.cast_ray(origin, direction);
    const auto east = scene.cast_ray(origin + kTwinOffset, direction);
    ASSERT_TRUE(west && east);
    EXPECT_NEAR(west->t, east->t, 1e-9);
    EXPECT_NE(west->surface, east->surface);
    EXPECT_LT((scene.colour(*west, 0.003) - scene.colour(*east, 0.003)).norm(), 1e-3);
  }
}

TEST(SyntheticScene, RaysPassTheDoorwayIntoTheSecondRoom) {
  const SyntheticScene& scene = test::shared_scene(Preset::kLong);
  // Level through the doorway at head height: the bookcase at x = 7.2.
  auto hit = scene.cast_ray(Vector3d(1.0, kDoorwayY, 1.5), Vector3d(1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), 7.2, 1e-12);
  // Beside the doorway: the partition wall.
  hit = scene.cast_ray(Vector3d(1.0, 1.0, 1.5), Vector3d(1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), 2.5, 1e-12);
}

TEST(SyntheticScene, ATwinMustRepeatAnEarlierPieceOfItsShape) {
  SceneDescription d = furnished_room_description();
  Furniture copy = d.furniture[0];
  copy.texture_twin = 1;  // the cabinet: other parts
  d.furniture.push_back(copy);
  EXPECT_THROW(SyntheticScene{d}, std::invalid_argument);
  d.furniture.back().texture_twin = int(d.furniture.size()) - 1;  // itself
  EXPECT_THROW(SyntheticScene{d}, std::invalid_argument);
}

}  // namespace
}  // namespace slamkit::synth
