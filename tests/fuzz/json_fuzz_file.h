// The JSON readers take a path: the fuzzers hand them the bytes through a
// private temporary file.
#ifndef TPOPT_TESTS_FUZZ_JSON_FUZZ_FILE_H_
#define TPOPT_TESTS_FUZZ_JSON_FUZZ_FILE_H_

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

inline std::string FuzzFile(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/tpopt_fuzz_" + std::to_string(getpid()) + ".json";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return path;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  return path;
}

#endif  // TPOPT_TESTS_FUZZ_JSON_FUZZ_FILE_H_
