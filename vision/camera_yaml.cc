// camera.yaml reading and writing (DESIGN §5.1, docs/recording-format.md).
#include <cmath>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <stdexcept>
#include <string>

#include "field_models/yaml_precheck.h"
#include "vision/camera_model.h"

namespace houghloc {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& what) {
  throw std::runtime_error(path + ": key '" + key + "': " + what);
}

/// Image sides above this are refused: no robot camera has them, and the vision allocates per
/// pixel (tests/fuzz/camera_yaml: a width of 100000000280 asked for 9.7 GB).
constexpr int kMaxImageSidePx = 16384;

int readImageSide(const cv::FileNode& root, const std::string& path, const std::string& key) {
  const cv::FileNode node = root[key];
  if (node.empty()) fail(path, key, "missing");
  if (!node.isInt()) fail(path, key, "expected an integer");
  const double exact = node.real();  // the value as OpenCV stored it
  if (!(exact >= 1 && exact <= kMaxImageSidePx))
    fail(path, key, "must be 1 to " + std::to_string(kMaxImageSidePx) + " pixels");
  return static_cast<int>(node);
}

/// Numbers of an `!!opencv-matrix` (any shape) or of a plain sequence `[a, b, ...]`.
std::vector<double> readNumbers(const cv::FileNode& node, const std::string& path,
                                const std::string& key) {
  std::vector<double> values;
  if (node.isMap()) {
    if (node["data"].empty()) fail(path, key, "not an OpenCV matrix (rows, cols, dt, data)");
    // Checked before OpenCV reads it: a non-integer cols made it allocate 48 GB (tests/fuzz).
    const cv::FileNode rows = node["rows"], cols = node["cols"];
    if (!rows.isInt() || !cols.isInt() || static_cast<int>(rows) < 1 ||
        static_cast<int>(cols) < 1 ||
        static_cast<std::size_t>(static_cast<int>(rows)) * static_cast<int>(cols) !=
            node["data"].size()) {
      fail(path, key, "rows and cols must be positive integers whose product is the data count");
    }
    cv::Mat mat;
    try {
      node >> mat;
    } catch (const cv::Exception& e) {
      fail(path, key, std::string("not an OpenCV matrix: ") + e.what());
    }
    if (mat.channels() != 1) fail(path, key, "expected a single-channel matrix");
    mat.convertTo(mat, CV_64F);
    values.assign(mat.begin<double>(), mat.end<double>());
  } else if (node.isSeq()) {
    for (const cv::FileNode& item : node) {
      if (!item.isReal() && !item.isInt()) fail(path, key, "expected numbers");
      values.push_back(static_cast<double>(item));
    }
  } else {
    fail(path, key, "expected a matrix or a sequence of numbers");
  }
  for (double v : values) {
    if (!std::isfinite(v)) fail(path, key, "contains a non-finite number");
  }
  return values;
}

/// The keys of an opened camera.yaml (DESIGN §5.1).
CameraIntrinsics readIntrinsics(const cv::FileNode& root, const std::string& path) {
  CameraIntrinsics in;
  in.image_width = readImageSide(root, path, "image_width");
  in.image_height = readImageSide(root, path, "image_height");

  const cv::FileNode matrix_node = root["camera_matrix"];
  if (matrix_node.empty()) fail(path, "camera_matrix", "missing");
  const std::vector<double> k = readNumbers(matrix_node, path, "camera_matrix");
  if (k.size() != 9)
    fail(path, "camera_matrix", "expected 3x3 = 9 numbers, got " + std::to_string(k.size()));
  in.camera_matrix = cv::Matx33d(k.data());

  const cv::FileNode model_node = root["model"];
  if (!model_node.empty()) {
    if (!model_node.isString()) fail(path, "model", "expected pinhole or fisheye");
    const std::string model = static_cast<std::string>(model_node);
    if (model == "fisheye") {
      in.model = DistortionModel::kFisheye;
    } else if (model != "pinhole") {
      fail(path, "model", "unknown model '" + model + "' (expected pinhole or fisheye)");
    }
  }
  // Missing distortion means an ideal lens; an empty matrix is accepted for the same reason.
  const cv::FileNode distortion_node = root["distortion_coefficients"];
  if (!distortion_node.empty()) {
    in.distortion = readNumbers(distortion_node, path, "distortion_coefficients");
  }
  try {
    LensDistortion(in.model, in.distortion);
  } catch (const std::invalid_argument& e) {
    fail(path, "distortion_coefficients", e.what());
  }
  try {
    validateCameraIntrinsics(in);
  } catch (const std::invalid_argument& e) {
    fail(path, "camera_matrix", e.what());
  }
  return in;
}
}  // namespace

CameraIntrinsics loadCameraYaml(const std::string& path) {
  // Checked first because OpenCV logs to stderr when it cannot open a file (libraries stay quiet).
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open camera file");
  checkYamlBeforeFileStorage(readTextFile(path), path);  // FileStorage hangs on some malformed YAML
  cv::FileStorage fs;
  try {
    if (!fs.open(path, cv::FileStorage::READ)) {
      throw std::runtime_error(path + ": cannot open camera file");
    }
    const cv::FileNode root = fs.root();
    // operator[] of a non-map node throws a cv::Exception without the file (tests/fuzz).
    if (!root.isMap()) throw std::runtime_error(path + ": expected a map of keys at the top level");
    return readIntrinsics(root, path);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path + ": cannot parse camera file: " + e.what());
  } catch (const std::length_error& e) {
    // A malformed key (":ols: 3") can make OpenCV 4.6 hand out a garbage string (tests/fuzz).
    throw std::runtime_error(path + ": malformed key or value (" + e.what() + ")");
  }
}

void saveCameraYaml(const std::string& path, const CameraIntrinsics& intrinsics) {
  try {
    validateCameraIntrinsics(intrinsics);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": refusing to write invalid intrinsics: " + e.what());
  }
  cv::FileStorage fs;
  try {
    if (!fs.open(path, cv::FileStorage::WRITE)) {
      throw std::runtime_error(path + ": cannot open camera file for writing");
    }
    fs << "image_width" << intrinsics.image_width;
    fs << "image_height" << intrinsics.image_height;
    // OpenCV writes doubles with 17 significant digits, so a save/load round trip is exact.
    fs << "camera_matrix" << cv::Mat(intrinsics.camera_matrix);
    // An ideal lens is written as an empty sequence: OpenCV cannot store a 1x0 matrix.
    if (intrinsics.distortion.empty()) {
      fs << "distortion_coefficients"
         << "["
         << "]";
    } else {
      fs << "distortion_coefficients" << cv::Mat(intrinsics.distortion).reshape(1, 1);
    }
    fs << "model" << (intrinsics.model == DistortionModel::kFisheye ? "fisheye" : "pinhole");
    fs.release();
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path + ": cannot write camera file: " + e.what());
  }
}

}  // namespace houghloc
