#include "lvslam/io/image_file.h"

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;
using testing::TempDir;

// A textured 8-bit BGR PNG written by OpenCV, as the simulator writes them.
std::string writePng(const TempDir& dir, const std::string& name) {
  cv::Mat image(48, 64, CV_8UC3);
  cv::randu(image, 0, 255);
  cv::imwrite(dir.file(name), image);
  return dir.file(name);
}

std::string bytesOf(const std::string& path) { return testing::slurpBinary(path); }

TEST(ImageFile, ReadsWhatImreadReads) {
  TempDir dir;
  const std::string path = writePng(dir, "a.png");
  const cv::Mat mine = readImageFile(path), theirs = cv::imread(path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(mine.type(), theirs.type());
  EXPECT_EQ(cv::norm(mine, theirs, cv::NORM_INF), 0.0);
  cv::Mat gray(30, 40, CV_8UC1, cv::Scalar(7));
  cv::imwrite(dir.file("g.png"), gray);
  EXPECT_EQ(readImageFile(dir.file("g.png")).type(), CV_8UC1);
}

TEST(ImageFile, TruncatedPngNamesTheChunkAndTheByte) {
  TempDir dir;
  const std::string bytes = bytesOf(writePng(dir, "a.png"));
  dir.write("t.png", bytes.substr(0, bytes.size() / 2));
  const std::string msg = errorMessageOf([&] { readImageFile(dir.file("t.png")); });
  EXPECT_NE(msg.find("t.png: damaged PNG: the file ends at byte " + std::to_string(bytes.size() / 2)),
            std::string::npos) << msg;
  EXPECT_NE(msg.find("'IDAT'"), std::string::npos) << msg;
}

TEST(ImageFile, OverwrittenBytesFailTheChunksCrc) {
  TempDir dir;
  std::string bytes = bytesOf(writePng(dir, "a.png"));
  bytes.replace(bytes.size() / 2, 8, "\xff\xff\xff\xff\xff\xff\xff\xff");
  dir.write("c.png", bytes);
  const std::string msg = errorMessageOf([&] { readImageFile(dir.file("c.png")); });
  EXPECT_NE(msg.find("c.png: damaged PNG: chunk 'IDAT' at byte"), std::string::npos) << msg;
  EXPECT_NE(msg.find("fails its CRC"), std::string::npos) << msg;
}

TEST(ImageFile, EmptyAndNotAPng) {
  TempDir dir;
  dir.write("e.png", "");
  EXPECT_NE(errorMessageOf([&] { readImageFile(dir.file("e.png")); }).find("e.png: empty file"), std::string::npos);
  dir.write("x.png", "GIF89a not a png at all");
  EXPECT_NE(errorMessageOf([&] { readImageFile(dir.file("x.png")); }).find("x.png: not a PNG file"),
            std::string::npos);
  dir.write("x.jpg", "not a jpeg");
  EXPECT_NE(errorMessageOf([&] { readImageFile(dir.file("x.jpg")); }).find("x.jpg: cannot decode image"),
            std::string::npos);
}

}  // namespace
}  // namespace lvslam
