#include "safecell/camera/pinhole_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <string>
#include <vector>

#include "random_camera.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// fx 500, fy 400, principal point (320, 240), 640 x 480 px, camera frame = cell frame.
CameraIntrinsics simple_intrinsics() {
  CameraIntrinsics intrinsics;
  intrinsics.fx_px = 500.0;
  intrinsics.fy_px = 400.0;
  intrinsics.cx_px = 320.0;
  intrinsics.cy_px = 240.0;
  intrinsics.width_px = 640;
  intrinsics.height_px = 480;
  return intrinsics;
}

PinholeCamera simple_camera(const LensDistortion& distortion = {}) {
  CameraIntrinsics intrinsics = simple_intrinsics();
  intrinsics.distortion = distortion;
  return {"simple", intrinsics, Eigen::Isometry3d::Identity()};
}

// The message of the CameraError that `make` raises.
std::string error_of(const std::function<void()>& make) {
  try {
    make();
  } catch (const CameraError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string error_of(const CameraIntrinsics& intrinsics,
                     const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity(),
                     const std::string& name = "bad") {
  return error_of([&] { static_cast<void>(PinholeCamera(name, intrinsics, pose)); });
}

// Distance of a point from the line of a ray, and whether it lies ahead of the origin.
double distance_from_ray(const Ray& ray, const Eigen::Vector3d& point_m) {
  const Eigen::Vector3d offset = point_m - ray.origin_m;
  return (offset - offset.dot(ray.direction) * ray.direction).norm();
}

TEST(PinholeCamera, ProjectsByHand) {
  const PinholeCamera camera = simple_camera();
  // (0.2, -0.1, 2) -> normalised (0.1, -0.05) -> (500 * 0.1 + 320, 400 * -0.05 + 240).
  EXPECT_EQ(camera.project({0.2, -0.1, 2.0}), Eigen::Vector2d(370.0, 220.0));
  EXPECT_EQ(camera.project({0.0, 0.0, 5.0}), Eigen::Vector2d(320.0, 240.0));
  EXPECT_EQ(camera.position_m(), Eigen::Vector3d::Zero());

  // k1 = 0.1, p1 = 0.01: r^2 = 0.0125, radial = 1.00125;
  // x_d = 0.1 * 1.00125 + 2 * 0.01 * 0.1 * -0.05 = 0.100025 -> u = 370.0125;
  // y_d = -0.05 * 1.00125 + 0.01 * (0.0125 + 2 * 0.0025) = -0.0498875 -> v = 220.045.
  const auto distorted = simple_camera({0.1, 0.0, 0.01, 0.0, 0.0}).project({0.2, -0.1, 2.0});
  ASSERT_TRUE(distorted.has_value());
  EXPECT_NEAR(distorted->x(), 370.0125, 1e-9);
  EXPECT_NEAR(distorted->y(), 220.045, 1e-9);
}

TEST(PinholeCamera, PlacedCameraByHand) {
  // Rotated a quarter turn about z and moved: x_camera = R x_cell + t.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() << 0, 1, 0,  //
      -1, 0, 0,              //
      0, 0, 1;
  pose.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  const PinholeCamera camera("placed", simple_intrinsics(), pose);
  // Centre: R c + t = 0 -> c = -R^T t = -(-2, 1, 3) = (2, -1, -3).
  EXPECT_TRUE(camera.position_m().isApprox(Eigen::Vector3d(2.0, -1.0, -3.0), 1e-15));
  // (0, 0, 1) -> camera (1, 2, 4) -> (500 / 4 + 320, 400 / 2 + 240).
  EXPECT_EQ(camera.project({0.0, 0.0, 1.0}), Eigen::Vector2d(445.0, 440.0));
  EXPECT_EQ(camera.cell_to_camera().matrix(), pose.matrix());
}

TEST(PinholeCamera, NothingOnOrBehindTheCameraPlaneProjects) {
  const PinholeCamera camera = simple_camera();
  EXPECT_FALSE(camera.project({0.0, 0.0, -1.0}).has_value());
  EXPECT_FALSE(camera.project({1.0, 1.0, 0.0}).has_value());
  EXPECT_FALSE(camera.project({0.0, 0.0, 1e-9}).has_value());
  EXPECT_FALSE(camera.project({kNan, 0.0, 1.0}).has_value());
  EXPECT_TRUE(camera.project({0.0, 0.0, 1e-8}).has_value());
}

TEST(PinholeCamera, LookAtByHand) {
  // From 3 m up straight down, up = +y, 90 degrees across 640 px: fx = fy = 320 / tan(45 deg).
  const PinholeCamera camera = PinholeCamera::look_at(
      "down", {0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, Eigen::Vector3d::UnitY(), 90.0 * kDeg, 640, 480);
  const CameraIntrinsics& in = camera.intrinsics();
  EXPECT_NEAR(in.fx_px, 320.0, 1e-12);
  EXPECT_EQ(in.fy_px, in.fx_px);
  EXPECT_EQ(in.cx_px, 319.5);  // OpenCV pixel centres: the image spans [-0.5, 639.5)
  EXPECT_EQ(in.cy_px, 239.5);
  EXPECT_EQ(in.distortion, LensDistortion{});
  EXPECT_TRUE(camera.position_m().isApprox(Eigen::Vector3d(0.0, 0.0, 3.0), 1e-15));
  // x right = +x, y down = -y: (1, 0.5, 1) is camera (1, -0.5, 2) -> (320 * 0.5 + 319.5,
  // 320 * -0.25 + 239.5).
  const auto pixel = camera.project({1.0, 0.5, 1.0});
  ASSERT_TRUE(pixel.has_value());
  EXPECT_NEAR(pixel->x(), 479.5, 1e-12);
  EXPECT_NEAR(pixel->y(), 159.5, 1e-12);
  // 45 degrees to either side lands on the left and right edges of the image.
  const auto left = camera.project({-2.0, 0.0, 1.0});
  const auto right = camera.project({2.0, 0.0, 1.0});
  ASSERT_TRUE(left.has_value() && right.has_value());
  EXPECT_NEAR(left->x(), -0.5, 1e-12);
  EXPECT_NEAR(right->x(), 639.5, 1e-12);
}

TEST(PinholeCamera, InImageFollowsOpenCvPixelCentres) {
  const PinholeCamera camera = simple_camera();
  EXPECT_TRUE(camera.in_image({-0.5, -0.5}));
  EXPECT_TRUE(camera.in_image({0.0, 0.0}));
  EXPECT_TRUE(camera.in_image({639.49, 479.49}));
  EXPECT_FALSE(camera.in_image({-0.51, 0.0}));
  EXPECT_FALSE(camera.in_image({0.0, -0.51}));
  EXPECT_FALSE(camera.in_image({639.5, 0.0}));
  EXPECT_FALSE(camera.in_image({0.0, 479.5}));
  EXPECT_FALSE(camera.in_image({kNan, 0.0}));
  EXPECT_FALSE(camera.in_image({0.0, kInf}));
}

TEST(PinholeCamera, BackProjectsByHand) {
  const Ray ray = simple_camera().back_project({370.0, 220.0});
  EXPECT_EQ(ray.origin_m, Eigen::Vector3d::Zero());
  EXPECT_TRUE(ray.direction.isApprox(Eigen::Vector3d(0.1, -0.05, 1.0).normalized(), 1e-15));
  EXPECT_NEAR(ray.direction.norm(), 1.0, 1e-15);
  EXPECT_TRUE(
      ray.point_at(std::sqrt(1.0125) * 2.0).isApprox(Eigen::Vector3d(0.2, -0.1, 2.0), 1e-15));
}

TEST(PinholeCamera, ProjectThenBackProjectPassesThroughThePoint) {
  test::PropertyRun run(200);
  int checked = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = test::random_camera(run.rng());
    for (int k = 0; k < 50; ++k) {
      const double z = test::uniform(run.rng(), 0.05, 8.0);
      const Eigen::Vector3d in_camera(z * test::uniform(run.rng(), -0.8, 0.8),
                                      z * test::uniform(run.rng(), -0.8, 0.8), z);
      const Eigen::Vector3d point_m = camera.camera_to_cell() * in_camera;
      const auto pixel = camera.project(point_m);
      if (!pixel || !camera.in_image(*pixel)) continue;
      const Ray ray = camera.back_project(*pixel);
      const double range_m = (point_m - ray.origin_m).norm();
      ASSERT_NEAR(ray.direction.norm(), 1.0, 1e-15);
      ASSERT_GT((point_m - ray.origin_m).dot(ray.direction), 0.0) << "iteration " << i;
      ASSERT_LE(distance_from_ray(ray, point_m), 1e-9 * range_m)
          << "iteration " << i << ", pixel " << pixel->transpose() << ", point "
          << point_m.transpose();
      ++checked;
    }
  }
  // Most drawn points fall in the image; the check must not pass by skipping them all.
  if (run.full_length()) {
    EXPECT_GT(checked, run.iterations() * 10);
  }
}

TEST(PinholeCamera, BackProjectThenProjectGivesThePixel) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = test::random_camera(run.rng());
    const CameraIntrinsics& in = camera.intrinsics();
    for (int k = 0; k < 50; ++k) {
      const Eigen::Vector2d pixel(test::uniform(run.rng(), -0.5, in.width_px - 0.5),
                                  test::uniform(run.rng(), -0.5, in.height_px - 0.5));
      const Ray ray = camera.back_project(pixel);
      const auto again = camera.project(ray.point_at(test::uniform(run.rng(), 0.1, 10.0)));
      ASSERT_TRUE(again.has_value()) << "iteration " << i << ", pixel " << pixel.transpose();
      ASSERT_LT((*again - pixel).norm(), 1e-8) << "iteration " << i;
    }
  }
}

TEST(PinholeCamera, ProjectionAgreesWithOpenCv) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = test::random_camera(run.rng());
    const CameraIntrinsics& in = camera.intrinsics();
    const LensDistortion& d = in.distortion;
    cv::Mat rotation(3, 3, CV_64F);
    cv::Mat translation(3, 1, CV_64F);
    for (int r = 0; r < 3; ++r) {
      translation.at<double>(r) = camera.cell_to_camera().translation()(r);
      for (int c = 0; c < 3; ++c)
        rotation.at<double>(r, c) = camera.cell_to_camera().linear()(r, c);
    }
    const cv::Matx33d k(in.fx_px, 0, in.cx_px, 0, in.fy_px, in.cy_px, 0, 0, 1);
    const std::vector<double> coefficients = {d.k1, d.k2, d.p1, d.p2, d.k3};

    std::vector<cv::Point3d> points;
    std::vector<Eigen::Vector2d> ours;
    while (points.size() < 20) {
      const Ray ray = camera.back_project({test::uniform(run.rng(), 0.0, in.width_px - 1.0),
                                           test::uniform(run.rng(), 0.0, in.height_px - 1.0)});
      const Eigen::Vector3d point_m = ray.point_at(test::uniform(run.rng(), 0.5, 6.0));
      points.emplace_back(point_m.x(), point_m.y(), point_m.z());
      ours.push_back(camera.project(point_m).value());
    }
    std::vector<cv::Point2d> theirs;
    // The rotation goes in as a matrix: a Rodrigues vector loses digits near half a turn.
    cv::projectPoints(points, rotation, translation, k, coefficients, theirs);
    for (std::size_t p = 0; p < points.size(); ++p) {
      ASSERT_NEAR(ours[p].x(), theirs[p].x, 1e-7) << "iteration " << i << ", point " << p;
      ASSERT_NEAR(ours[p].y(), theirs[p].y, 1e-7) << "iteration " << i << ", point " << p;
    }
  }
}

TEST(PinholeCamera, LookAtPutsTheTargetAtThePrincipalPointAndUpUp) {
  test::PropertyRun run(500);
  for (int i = 0; i < run.iterations(); ++i) {
    const Eigen::Vector3d position_m(test::uniform(run.rng(), -3, 3),
                                     test::uniform(run.rng(), -3, 3),
                                     test::uniform(run.rng(), -3, 3));
    const Eigen::Vector3d target_m(test::uniform(run.rng(), -3, 3), test::uniform(run.rng(), -3, 3),
                                   test::uniform(run.rng(), -3, 3));
    const Eigen::Vector3d up =
        Eigen::Vector3d(test::uniform(run.rng(), -1, 1), test::uniform(run.rng(), -1, 1),
                        test::uniform(run.rng(), -1, 1))
            .normalized();
    const Eigen::Vector3d view = (target_m - position_m).normalized();
    if ((target_m - position_m).norm() < 0.1 || view.cross(up).norm() < 0.1) continue;
    const PinholeCamera camera = PinholeCamera::look_at(
        "look", position_m, target_m, up, test::uniform(run.rng(), 10, 170) * kDeg,
        static_cast<int>(test::uniform(run.rng(), 100, 2000)),
        static_cast<int>(test::uniform(run.rng(), 100, 2000)));
    const CameraIntrinsics& in = camera.intrinsics();
    const Eigen::Vector2d centre(in.cx_px, in.cy_px);
    EXPECT_TRUE(camera.position_m().isApprox(position_m, 1e-12));
    const auto target = camera.project(target_m);
    ASSERT_TRUE(target.has_value()) << "iteration " << i;
    EXPECT_LT((*target - centre).norm(), 1e-9) << "iteration " << i;
    // A step along `up` from the target moves straight up the image.
    const auto above = camera.project(target_m + 0.01 * (target_m - position_m).norm() * up);
    ASSERT_TRUE(above.has_value()) << "iteration " << i;
    EXPECT_NEAR(above->x(), in.cx_px, 1e-9) << "iteration " << i;
    EXPECT_LT(above->y(), in.cy_px) << "iteration " << i;
  }
}

TEST(PinholeCamera, RefusesValuesThatMakeNoCamera) {
  EXPECT_EQ(error_of([] {
              CameraIntrinsics in = simple_intrinsics();
              in.fx_px = -1.0;
              static_cast<void>(PinholeCamera("bad", in, Eigen::Isometry3d::Identity()));
            }),
            "camera 'bad': intrinsics.fx_px: -1, expected a finite focal length in pixels > 0");

  struct Case {
    std::function<void(CameraIntrinsics&)> change;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](CameraIntrinsics& in) { in.fy_px = kNan; }, "camera 'bad': intrinsics.fy_px: nan, "},
      {[](CameraIntrinsics& in) { in.fx_px = kInf; }, "camera 'bad': intrinsics.fx_px: inf, "},
      {[](CameraIntrinsics& in) { in.fy_px = 0.0; }, "camera 'bad': intrinsics.fy_px: 0, "},
      {[](CameraIntrinsics& in) { in.cx_px = -kInf; }, "camera 'bad': intrinsics.cx_px: -inf, "},
      {[](CameraIntrinsics& in) { in.cy_px = kNan; }, "camera 'bad': intrinsics.cy_px: nan, "},
      {[](CameraIntrinsics& in) { in.width_px = 0; }, "camera 'bad': intrinsics.width_px: 0 px, "},
      {[](CameraIntrinsics& in) { in.height_px = -3; },
       "camera 'bad': intrinsics.height_px: -3 px, "},
      {[](CameraIntrinsics& in) { in.distortion.k2 = kNan; },
       "camera 'bad': intrinsics.distortion: nan, "},
      // k1 = -0.5 folds at r = 0.82, where the distorted radius peaks at 0.54; the image
      // corners sit at a distorted radius of 0.88.
      {[](CameraIntrinsics& in) { in.distortion.k1 = -0.5; },
       "camera 'bad': intrinsics.distortion: [-0.5, 0, 0, 0, 0] fold the image over before its "
       "corner pixel (-0.5, -0.5), expected"},
  };
  for (const Case& c : cases) {
    CameraIntrinsics intrinsics = simple_intrinsics();
    c.change(intrinsics);
    const std::string message = error_of(intrinsics);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << message;
    EXPECT_NE(message.find("expected"), std::string::npos) << message;
  }
  // Barrel distortion that keeps to the image is fine.
  CameraIntrinsics barrel = simple_intrinsics();
  barrel.distortion.k1 = -0.1;  // peaks at a distorted radius of 1.22
  EXPECT_EQ(error_of(barrel), "(no error)");
}

TEST(PinholeCamera, RefusesPosesThatAreNotRigid) {
  Eigen::Isometry3d scaled = Eigen::Isometry3d::Identity();
  scaled.linear() *= 2.0;
  EXPECT_EQ(error_of(simple_intrinsics(), scaled),
            "camera 'bad': cell_to_camera.rotation: [[2, 0, 0], [0, 2, 0], [0, 0, 2]] is not a "
            "rotation (max |R^T R - I| = 3, det = 8), expected an orthonormal matrix with "
            "determinant +1");
  Eigen::Isometry3d mirrored = Eigen::Isometry3d::Identity();
  mirrored.linear()(2, 2) = -1.0;
  const std::string message = error_of(simple_intrinsics(), mirrored);
  EXPECT_NE(message.find("cell_to_camera.rotation: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("det = -1"), std::string::npos) << message;
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation().y() = kNan;
  EXPECT_EQ(
      error_of(simple_intrinsics(), far)
          .rfind("camera 'bad': cell_to_camera.translation: nan, expected a finite number", 0),
      0u);
  EXPECT_EQ(error_of(simple_intrinsics(), Eigen::Isometry3d::Identity(), ""),
            "camera '': name: empty, expected a camera name");
}

TEST(PinholeCamera, NearlyOrthonormalRotationsAreMadeExact) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.linear()(0, 1) += 1e-7;  // as from a file printed with few digits
  const PinholeCamera camera("near", simple_intrinsics(), pose);
  const Eigen::Matrix3d rotation = camera.cell_to_camera().linear();
  EXPECT_LT((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT((rotation - pose.linear()).norm(), 1e-6);
  // An exact rotation is kept as given.
  pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_EQ(PinholeCamera("exact", simple_intrinsics(), pose).cell_to_camera().linear(),
            pose.linear());
}

TEST(PinholeCamera, LookAtRefusesDegenerateViews) {
  const Eigen::Vector3d position(1.0, 2.0, 3.0);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(error_of([&] {
              static_cast<void>(PinholeCamera::look_at("v", position, position, up, 1.0, 64, 48));
            }),
            "camera 'v': look_at.target_m: (1, 2, 3) is the camera position, expected a point "
            "away from it");
  EXPECT_EQ(
      error_of([&] {
        static_cast<void>(PinholeCamera::look_at("v", position, {1.0, 2.0, 0.0}, up, 1.0, 64, 48));
      }),
      "camera 'v': look_at.up: (0, 0, 1) is along the view direction (0, 0, -1), expected "
      "a direction across it");
  for (const double fov : {0.0, std::numbers::pi, -1.0, kNan}) {
    const std::string message = error_of([&] {
      static_cast<void>(PinholeCamera::look_at("v", position, {0, 0, 0}, up, fov, 64, 48));
    });
    EXPECT_EQ(message.rfind("camera 'v': look_at.horizontal_fov_rad: ", 0), 0u) << message;
  }
  EXPECT_EQ(error_of([&] {
              static_cast<void>(PinholeCamera::look_at("v", position, {0, 0, 0}, up, 1.0, 0, 48));
            }).rfind("camera 'v': intrinsics.width_px: 0 px", 0),
            0u);
  EXPECT_EQ(
      error_of([&] {
        static_cast<void>(PinholeCamera::look_at("v", {kNan, 0, 0}, {0, 0, 0}, up, 1.0, 64, 48));
      }).rfind("camera 'v': look_at: position (nan, 0, 0)", 0),
      0u);
}

TEST(PinholeCamera, TheLensModelIsNotUsedPastItsFold) {
  // k1 = -0.1 folds at r^2 = 1 / 0.3 (r = 1.83); the image reaches r = 0.88.
  const PinholeCamera camera = simple_camera({-0.1, 0.0, 0.0, 0.0, 0.0});
  EXPECT_TRUE(camera.project({1.8, 0.0, 1.0}).has_value());
  EXPECT_FALSE(camera.project({1.9, 0.0, 1.0}).has_value());
  EXPECT_FALSE(camera.project({0.0, 5.0, 1.0}).has_value());
  // A pixel far out has no ray under this lens, but does under an ideal one.
  const std::string message = error_of([&] {
    static_cast<void>(camera.back_project({320.0 + 500.0 * 5.0, 240.0}));
  });
  EXPECT_EQ(message.rfind("camera 'simple': back_project: pixel (2820, 240) has no ray", 0), 0u)
      << message;
  EXPECT_NO_THROW(static_cast<void>(simple_camera().back_project({2820.0, 240.0})));
  EXPECT_THROW(static_cast<void>(simple_camera().back_project({kNan, 240.0})), CameraError);
}

}  // namespace
}  // namespace safecell
