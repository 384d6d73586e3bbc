// Corrupted FCLIB files that libfclib would answer by exiting the process (a failed HDF5 read,
// an allocation of 2^31 - 1 entries) are refused by our checks first, with the file named;
// HDF5 files are recognised by their signature, not by their name.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "solvers/io/fclib_file.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

#if __has_include(<hdf5/serial/hdf5.h>)
#include <hdf5/serial/hdf5.h>
#define IMPACTBENCH_TEST_HAS_HDF5 1
#elif __has_include(<hdf5.h>)
#include <hdf5.h>
#define IMPACTBENCH_TEST_HAS_HDF5 1
#endif

namespace impactbench::solvers {
namespace {

std::filesystem::path hardening_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impactbench_fclib_hardening_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

/// A valid local problem (4 contacts, 3D) written by our own writer.
std::filesystem::path valid_local_file(const std::string& name) {
  const std::filesystem::path path = hardening_file(name);
  write_fclib_local(random_friction_problem({4, 6, 3, false, 2}), path, "hardening");
  return path;
}

std::string rejection_of(const std::filesystem::path& path) {
  try {
    read_fclib_file(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(FclibHardening, Hdf5IsRecognisedBySignatureNotByName) {
  const auto valid = valid_local_file("valid.hdf5");
  const auto renamed = hardening_file("upper.HDF5");
  std::filesystem::rename(valid, renamed);
  EXPECT_TRUE(is_hdf5_file(renamed));
  EXPECT_EQ(rejection_of(renamed), "");
  const auto text = hardening_file("text.h5");
  std::ofstream(text) << "5\n";
  EXPECT_FALSE(is_hdf5_file(text));
  std::filesystem::remove(renamed);
  std::filesystem::remove(text);
}

#ifdef IMPACTBENCH_TEST_HAS_HDF5

/// Replaces dataset `name` of the file at `path` by `values` of HDF5 type `type`.
template <typename T>
void replace_dataset(const std::filesystem::path& path, const std::string& name, hid_t type,
                     const T* values, hsize_t count) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0) H5Ldelete(file, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Screate_simple(1, &count, nullptr);
  const hid_t dataset =
      H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(dataset, 0);
  ASSERT_GE(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), 0);
  H5Dclose(dataset);
  H5Sclose(space);
  H5Fclose(file);
}

TEST(FclibHardening, HugeNzmaxIsRefusedBeforeLibfclibAllocatesIt) {
  const auto path = valid_local_file("nzmax.hdf5");
  const int huge = 2147483647;
  replace_dataset(path, "/fclib_local/W/nzmax", H5T_NATIVE_INT, &huge, 1);
  const std::string message = rejection_of(path);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("/fclib_local/W/nzmax = 2147483647 exceeds m·n = 144"), std::string::npos)
      << message;
  std::filesystem::remove(path);
}

TEST(FclibHardening, TextWhereNumbersBelongIsRefused) {
  const auto path = valid_local_file("text_q.hdf5");
  const hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, 4);
  const char values[12 * 4] = "abc";
  replace_dataset(path, "/fclib_local/vectors/q", text, values, 12);
  H5Tclose(text);
  const std::string message = rejection_of(path);
  EXPECT_NE(message.find("/fclib_local/vectors/q does not hold numbers"), std::string::npos)
      << message;
  std::filesystem::remove(path);
}

TEST(FclibHardening, NumbersWhereTheTitleBelongsAreRefused) {
  const auto path = valid_local_file("number_title.hdf5");
  const double value = 1.5;
  replace_dataset(path, "/fclib_local/info/title", H5T_NATIVE_DOUBLE, &value, 1);
  const std::string message = rejection_of(path);
  EXPECT_NE(message.find("/fclib_local/info/title does not hold text"), std::string::npos)
      << message;
  std::filesystem::remove(path);
}

#endif

}  // namespace
}  // namespace impactbench::solvers
