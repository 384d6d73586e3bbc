// Reading toss files: the values and their order (qw first), and every refusal as "path:line:".
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "lib/validation/toss_csv.hpp"

namespace impactbench::validation {
namespace {

const std::string kHeader = "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";
// A quarter turn about z: (w, x, y, z) = (cos 45°, 0, 0, sin 45°).
const std::string kRow0 = "0,1,2,3,0.7071067811865476,0,0,0.7071067811865476,4,5,6,7,8,9\n";
const std::string kRow1 = "0.5,1,2,3,1,0,0,0,4,5,6,7,8,9\n";

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("impactbench_" + name + ".csv");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string refusal(const std::string& name, const std::string& text) {
  const auto path = write(name, text);
  try {
    read_toss(path);
  } catch (const TossDataError& error) {
    std::filesystem::remove(path);
    return error.what();
  }
  std::filesystem::remove(path);
  return "accepted";
}

TEST(TossCsv, ReadsColumnsByNameWithTheScalarPartFirst) {
  // Columns in another order and an extra one: read by name.
  const auto path = write("toss_007",
                          "qz,qy,qx,qw,t,x,y,z,extra,vx,vy,vz,wx,wy,wz\n"
                          "0.6,0,0,0.8,0,1,2,3,99,4,5,6,7,8,9\n"
                          "0,0,0,1,0.25,1,2,3,99,4,5,6,7,8,9\n");
  const Toss toss = read_toss(path);
  std::filesystem::remove(path);
  EXPECT_EQ(toss.name, "impactbench_toss_007");
  ASSERT_EQ(toss.samples.size(), 2u);
  const TossSample& s = toss.samples[0];
  EXPECT_EQ(s.orientation.w(), 0.8);
  EXPECT_EQ(s.orientation.z(), 0.6);
  EXPECT_EQ(s.position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(s.velocity, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(s.angular_velocity_body, Eigen::Vector3d(7, 8, 9));
  EXPECT_EQ(toss.samples[1].t, 0.25);
}

TEST(TossCsv, RefusesBadFilesWithPathAndLine) {
  const auto expect = [](const std::string& name, const std::string& text, const std::string& where,
                         const std::string& what) {
    const std::string message = refusal(name, text);
    const std::string prefix = "impactbench_" + name + ".csv:" + where + ": ";
    EXPECT_NE(message.find(prefix), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect("missing", "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy\n" + kRow0, "1", "missing column 'wz'");
  expect("nan", kHeader + kRow0 + "0.5,1,nan,3,1,0,0,0,4,5,6,7,8,9\n", "3", "column y is nan");
  expect("norm", kHeader + kRow0 + "0.5,1,2,3,1.5,0,0,0,4,5,6,7,8,9\n", "3",
         "quaternion (qw, qx, qy, qz) has norm 1.5, not 1 within 1e-6");
  expect("short", kHeader + kRow0, "2", "1 sample(s); a toss needs at least 2");
  expect("time", kHeader + kRow0 + kRow1 + "0.5,1,2,3,1,0,0,0,4,5,6,7,8,9\n", "4",
         "time 0.5 does not increase (previous 0.5)");
  expect("fields", kHeader + kRow0 + "0.5;1;2\n", "3", "not CSV: 1 fields, the header has 14");
  expect("binary", std::string("\x89PNG\r\n\x1a\n\0\0", 10), "1", "not CSV text (byte 0x89)");
  expect("nul", kHeader + kRow0 + std::string("0.5,1,2\0", 8), "3", "not CSV text (byte 0x00)");
  expect("word", kHeader + kRow0 + "0.5,1,2,3,1,0,0,0,four,5,6,7,8,9\n", "3",
         "column vx: 'four' is not a number");
  expect("empty", "", "1", "empty file");
  // 1e-7 off unit norm is within the tolerance and normalised.
  const auto path = write("near", kHeader + kRow0 + "0.5,1,2,3,1.0000001,0,0,0,4,5,6,7,8,9\n");
  EXPECT_EQ(read_toss(path).samples[1].orientation.w(), 1.0);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace impactbench::validation
