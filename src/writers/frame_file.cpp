#include "writers/frame_file.hpp"

#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace finseg {
namespace {

namespace fs = std::filesystem;

// Layout (native byte order, doubles as IEEE 754): the header, then one record per frame: its
// length in bytes after the length field (u64), t (f64), the orientations (u64 n, 9 n f64, row
// by row), each vector field of visit_frame_vectors (u64 n, 3 n f64), each array of
// visit_frame_arrays (u64 n, n f64).
constexpr char kMagic[8] = {'F', 'S', 'E', 'G', 'F', 'R', 'M', '1'};
constexpr std::size_t kHashBytes = 16;  // scene_hash(): 16 hex digits
constexpr std::uint64_t kHeaderBytes = sizeof(kMagic) + kHashBytes;

std::string header(const std::string& run_hash) {
  std::string h(kMagic, sizeof(kMagic));
  std::string id = run_hash.substr(0, kHashBytes);
  id.resize(kHashBytes, ' ');
  return h + id;
}

void put_u64(std::string& out, std::uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(v));
}

void put_doubles(std::string& out, const double* x, std::size_t n) {
  if (n > 0) out.append(reinterpret_cast<const char*>(x), n * sizeof(double));
}

std::string record(const Frame& f) {
  std::string body;
  put_doubles(body, &f.t, 1);
  put_u64(body, f.R_WB.size());
  for (const Mat3& m : f.R_WB) {
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = m;
    put_doubles(body, r.data(), 9);
  }
  visit_frame_vectors(f, [&](const char*, const std::vector<Vec3>& v) {
    put_u64(body, v.size());
    for (const Vec3& x : v) put_doubles(body, x.data(), 3);
  });
  visit_frame_arrays(f, [&](const char*, const std::vector<double>& v) {
    put_u64(body, v.size());
    put_doubles(body, v.data(), v.size());
  });
  std::string out;
  put_u64(out, body.size());
  return out + body;
}

// Reads a record's fields from `p` (its `size` bytes after the length); false if they do not
// fill it exactly.
class RecordReader {
 public:
  RecordReader(const char* p, std::uint64_t size) : p_(p), left_(size) {}
  bool doubles(double* x, std::uint64_t n) {
    if (n == 0) return true;  // (x may be null: an empty vector's data)
    if (n > left_ / sizeof(double)) return false;
    std::memcpy(x, p_, n * sizeof(double));
    p_ += n * sizeof(double);
    left_ -= n * sizeof(double);
    return true;
  }
  // A count of entries of `each` doubles, which must fit in what is left of the record.
  bool count(std::uint64_t& n, std::uint64_t each) {
    if (left_ < sizeof(n)) return false;
    std::memcpy(&n, p_, sizeof(n));
    p_ += sizeof(n);
    left_ -= sizeof(n);
    return n <= left_ / (each * sizeof(double));
  }
  bool done() const { return left_ == 0; }

 private:
  const char* p_;
  std::uint64_t left_;
};

bool parse_record(const char* p, std::uint64_t size, Frame& f) {
  RecordReader in(p, size);
  std::uint64_t n = 0;
  if (!in.doubles(&f.t, 1) || !in.count(n, 9)) return false;
  f.R_WB.resize(n);
  for (Mat3& m : f.R_WB) {
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r;
    if (!in.doubles(r.data(), 9)) return false;
    m = r;
  }
  bool ok = true;
  visit_frame_vectors(f, [&](const char*, std::vector<Vec3>& v) {
    ok = ok && in.count(n, 3);
    if (!ok) return;
    v.resize(n);
    for (Vec3& x : v) ok = ok && in.doubles(x.data(), 3);
  });
  visit_frame_arrays(f, [&](const char*, std::vector<double>& v) {
    ok = ok && in.count(n, 1);
    if (!ok) return;
    v.resize(n);
    ok = in.doubles(v.data(), n);
  });
  return ok && in.done();
}

std::uint64_t file_size(const std::string& path) {
  std::error_code ec;
  const auto n = fs::file_size(path, ec);
  return ec ? 0 : n;
}

// How many leading records of the file are `frames`' (same run, same times), and where they
// end; {0, 0} when the header is another run's or missing.
std::pair<std::size_t, std::uint64_t> kept_records(const std::string& path,
                                                   const std::string& run_hash,
                                                   const std::vector<Frame>& frames) {
  std::ifstream in(path, std::ios::binary);
  const std::uint64_t size = file_size(path);
  std::string h(kHeaderBytes, '\0');
  if (!in || size < kHeaderBytes || !in.read(h.data(), kHeaderBytes) || h != header(run_hash))
    return {0, 0};
  std::size_t k = 0;
  std::uint64_t at = kHeaderBytes;
  for (; k < frames.size(); ++k) {
    std::uint64_t n = 0;
    double t = 0;
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(&n), sizeof(n)) ||
        !in.read(reinterpret_cast<char*>(&t), sizeof(t)) || n > size - at - sizeof(n) ||
        std::memcmp(&t, &frames[k].t, sizeof(t)) != 0)
      break;
    at += sizeof(n) + n;
  }
  return {k, at};
}

}  // namespace

std::uint64_t sync_frame_file(const std::string& path, const std::string& run_hash,
                              const std::vector<Frame>& frames) {
  auto [kept, end] = kept_records(path, run_hash, frames);
  std::error_code ec;
  if (end > 0) fs::resize_file(path, end, ec);
  if (ec) kept = end = 0;
  std::ofstream out(path, std::ios::binary | (end > 0 ? std::ios::app : std::ios::trunc));
  if (!out) throw OutputError(fmt::format("cannot open '{}' for writing", path));
  if (end == 0) out << header(run_hash);
  for (std::size_t k = kept; k < frames.size(); ++k) out << record(frames[k]);
  out.flush();
  if (!out) throw OutputError(fmt::format("cannot write '{}' (disk full?)", path));
  out.close();
  return file_size(path);
}

std::vector<Frame> read_frame_file(const std::string& path, const std::string& run_hash,
                                   std::size_t count, std::uint64_t bytes) {
  const std::uint64_t size = file_size(path);
  if (!fs::exists(path) || size < bytes) {
    throw InputError(path, "(file)",
                     fmt::format("holds {} bytes; the checkpoint's run.frames_file says {} (the "
                                 "frames recorded before it are missing)",
                                 fs::exists(path) ? size : 0, bytes));
  }
  std::ifstream in(path, std::ios::binary);
  std::string data(bytes, '\0');
  if (!in.read(data.data(), static_cast<std::streamsize>(bytes)))
    throw InputError(path, "(file)", "cannot be read");
  if (bytes < kHeaderBytes || data.compare(0, kHeaderBytes, header(run_hash)) != 0)
    throw InputError(path, "(header)", "not the frame file of this checkpoint's run");
  std::vector<Frame> frames(count);
  std::uint64_t at = kHeaderBytes;
  for (std::size_t k = 0; k < count; ++k) {
    std::uint64_t n = 0;
    if (bytes - at < sizeof(n)) throw InputError(path, fmt::format("frame {}", k), "missing");
    std::memcpy(&n, data.data() + at, sizeof(n));
    at += sizeof(n);
    if (n > bytes - at || !parse_record(data.data() + at, n, frames[k]))
      throw InputError(path, fmt::format("frame {}", k), "truncated or malformed");
    at += n;
  }
  if (at != bytes) {
    throw InputError(
        path, "(file)",
        fmt::format("its {} frames end at byte {}, the checkpoint says {}", count, at, bytes));
  }
  std::error_code ec;
  if (size > bytes) fs::resize_file(path, bytes, ec);
  return frames;
}

}  // namespace finseg
