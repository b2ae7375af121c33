#include "image/png_bands.hpp"

#include <sched.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "image/image.hpp"
#include "image/png_filters.hpp"

namespace clrt::image_detail {
namespace {

// At most this many bands: enough for two threads to share the work evenly when one of them is
// slowed by other work on the machine (measured: 32 bands balance better than 2 under load),
// few enough that the sync flushes cost nothing to speak of (5 bytes each). A band holds at
// least kMinBandRows rows so that matches still find the rows above.
constexpr int kMaxBands = 32;
constexpr int kMinBandRows = 16;
// The zlib header's first byte: deflate with a 32 KiB window, as deflateInit2's windowBits -15.
constexpr std::uint8_t kZlibMethod = 0x78;
constexpr int kWindowBits = -15;  // a raw deflate stream: the header and checksum are ours
constexpr int kMemLevel = 8;      // zlib's default

// Bytes without the zero-filling of std::vector::resize: a band's output buffer is sized to
// zlib's bound up front and mostly left unwritten.
class ByteBuffer {
 public:
  std::uint8_t* data() { return bytes_.get(); }
  std::size_t size() const { return size_; }
  std::size_t room() const { return capacity_ - size_; }
  std::uint8_t* end() { return bytes_.get() + size_; }
  void grew(std::size_t count) { size_ += count; }
  void reserve(std::size_t capacity) {
    if (capacity <= capacity_) return;
    std::unique_ptr<std::uint8_t[]> larger(new std::uint8_t[capacity]);
    if (size_ > 0) std::memcpy(larger.get(), bytes_.get(), size_);
    bytes_ = std::move(larger);
    capacity_ = capacity;
  }
  void push_back(std::uint8_t byte) {
    if (room() == 0) reserve(2 * capacity_ + 16);
    bytes_[size_++] = byte;
  }
  void release() {
    bytes_.reset();
    size_ = capacity_ = 0;
  }

 private:
  std::unique_ptr<std::uint8_t[]> bytes_;
  std::size_t size_ = 0, capacity_ = 0;
};

int zlib_strategy(PngStrategy strategy) {
  switch (strategy) {
    case PngStrategy::Default: return Z_DEFAULT_STRATEGY;
    case PngStrategy::Filtered: return Z_FILTERED;
    case PngStrategy::Rle: return Z_RLE;
    case PngStrategy::HuffmanOnly: return Z_HUFFMAN_ONLY;
  }
  return Z_DEFAULT_STRATEGY;
}

// The two header bytes deflate itself would write: its compression-level hint, and a check
// value making the pair a multiple of 31.
void append_zlib_header(ByteBuffer& out, const PngEncoding& encoding) {
  const bool fastest = encoding.strategy == PngStrategy::HuffmanOnly ||
                       encoding.strategy == PngStrategy::Rle || encoding.level < 2;
  const unsigned hint = fastest ? 0 : encoding.level < 6 ? 1 : encoding.level == 6 ? 2 : 3;
  unsigned flags = hint << 6;
  flags += 31 - (kZlibMethod * 256u + flags) % 31;
  out.push_back(kZlibMethod);
  out.push_back(static_cast<std::uint8_t>(flags));
}

struct Band {
  int first_row = 0, end_row = 0;
  ByteBuffer bytes;  // this band's part of the stream
  uLong adler = 0;   // Adler-32 of this band's filtered rows
  std::size_t filtered_bytes = 0;
  bool done = false;
  std::exception_ptr failure;
};

class Deflater {
 public:
  explicit Deflater(const PngEncoding& encoding) {
    if (deflateInit2(&stream_, encoding.level, Z_DEFLATED, kWindowBits, kMemLevel,
                     zlib_strategy(encoding.strategy)) != Z_OK)
      throw ImageError("PNG encoding failed: zlib could not start a compressor");
  }
  ~Deflater() { deflateEnd(&stream_); }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;

  // Compresses `size` bytes onto the end of `out`, growing it when zlib's bound was not enough
  // (only a flush can pass it, by a few bytes).
  void add(const std::uint8_t* data, std::size_t size, int flush, ByteBuffer& out) {
    // zlib counts input in 32 bits: a row of a billion pixels goes in parts.
    constexpr std::size_t kMaxPart = std::size_t{1} << 30;
    for (; size > kMaxPart; data += kMaxPart, size -= kMaxPart)
      add_part(data, kMaxPart, Z_NO_FLUSH, out);
    add_part(data, size, flush, out);
  }

  std::size_t bound(std::size_t size) { return deflateBound(&stream_, static_cast<uLong>(size)); }

 private:
  void add_part(const std::uint8_t* data, std::size_t size, int flush, ByteBuffer& out) {
    stream_.next_in = const_cast<Bytef*>(data);
    stream_.avail_in = static_cast<uInt>(size);
    do {
      if (out.room() == 0) out.reserve(2 * out.size() + 4096);
      const std::size_t room = out.room();
      stream_.next_out = out.end();
      stream_.avail_out = static_cast<uInt>(room);
      const int result = deflate(&stream_, flush);
      out.grew(room - stream_.avail_out);
      if (result == Z_STREAM_ERROR) throw ImageError("PNG encoding failed: zlib refused the data");
    } while (stream_.avail_out == 0 || stream_.avail_in > 0);
  }

  z_stream stream_{};
};

// The cores this process may run on: its affinity mask, so that `taskset` and a container's CPU
// set are respected (hardware_concurrency counts every core of the machine).
unsigned usable_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

// Filters and compresses band `band` of `bands`.
void compress_band(const EightBitRows& rows, bool rgba, const PngEncoding& encoding,
                   std::size_t band, std::vector<Band>& bands) {
  Band& out = bands[band];
  const std::size_t bpp = rgba ? 4 : 3;
  const std::size_t row_bytes = bpp * static_cast<std::size_t>(rows.width());
  std::vector<std::uint8_t> scratch(2 * 4 * static_cast<std::size_t>(rows.width()));
  std::vector<std::uint8_t> zeros(row_bytes, 0), filtered(1 + row_bytes);
  std::uint8_t* scratches[2] = {scratch.data(), scratch.data() + scratch.size() / 2};
  const auto row = [&](int y) {
    return rgba ? rows.rgba_row(0, y, scratches[y & 1]) : rows.rgb_row(0, y, scratches[y & 1]);
  };

  Deflater deflater(encoding);
  out.filtered_bytes = static_cast<std::size_t>(out.end_row - out.first_row) * (1 + row_bytes);
  const bool first = band == 0, last = band + 1 == bands.size();
  // Room for zlib's header and checksum too: the whole band is compressed without a copy.
  out.bytes.reserve(deflater.bound(out.filtered_bytes) + 16);
  if (first) append_zlib_header(out.bytes, encoding);
  out.adler = adler32(0, nullptr, 0);
  const std::uint8_t* previous = first ? zeros.data() : row(out.first_row - 1);
  for (int y = out.first_row; y < out.end_row; ++y) {
    const std::uint8_t* current = row(y);
    filter_row(encoding.filters, previous, current, row_bytes, bpp, filtered.data());
    out.adler = adler32_z(out.adler, filtered.data(), filtered.size());
    const int flush = y + 1 < out.end_row ? Z_NO_FLUSH : last ? Z_FINISH : Z_SYNC_FLUSH;
    deflater.add(filtered.data(), filtered.size(), flush, out.bytes);
    previous = current;
  }
}

// Runs compress_band on worker threads, each taking the next band not yet taken; stops and joins
// them when it goes out of scope, after the caller's last band or an exception.
class BandWorkers {
 public:
  BandWorkers(const EightBitRows& rows, bool rgba, const PngEncoding& encoding,
              std::vector<Band>& bands)
      : bands_(bands) {
    const std::size_t count = std::min<std::size_t>(usable_cores(), bands.size());
    try {
      for (std::size_t i = 0; i < count; ++i)
        threads_.emplace_back([this, &rows, rgba, &encoding] { work(rows, rgba, encoding); });
    } catch (...) {  // no destructor runs for a constructor that throws
      stop();
      throw;
    }
  }
  ~BandWorkers() { stop(); }
  BandWorkers(const BandWorkers&) = delete;
  BandWorkers& operator=(const BandWorkers&) = delete;

  // Waits for band `band`; rethrows its failure.
  Band& finished(std::size_t band) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return bands_[band].done; });
    if (bands_[band].failure) std::rethrow_exception(bands_[band].failure);
    return bands_[band];
  }

 private:
  void stop() {
    stop_ = true;
    for (std::thread& thread : threads_) thread.join();
  }

  void work(const EightBitRows& rows, bool rgba, const PngEncoding& encoding) {
    for (std::size_t band; !stop_ && (band = next_++) < bands_.size();) {
      std::exception_ptr failure;
      try {
        compress_band(rows, rgba, encoding, band, bands_);
      } catch (...) {
        failure = std::current_exception();
      }
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        bands_[band].failure = failure;
        bands_[band].done = true;
      }
      done_.notify_all();
    }
  }

  std::vector<Band>& bands_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable done_;
  std::vector<std::thread> threads_;  // last: started after everything they use
};

}  // namespace

void compress_png_rows(const EightBitRows& rows, bool rgba, const PngEncoding& encoding,
                       const std::function<void(const std::uint8_t*, std::size_t)>& emit) {
  const int height = rows.height();
  const int band_rows = std::max(kMinBandRows, (height + kMaxBands - 1) / kMaxBands);
  std::vector<Band> bands(static_cast<std::size_t>((height + band_rows - 1) / band_rows));
  for (std::size_t i = 0; i < bands.size(); ++i) {
    bands[i].first_row = static_cast<int>(i) * band_rows;
    bands[i].end_row = std::min(height, bands[i].first_row + band_rows);
  }
  uLong adler = 0;
  BandWorkers workers(rows, rgba, encoding, bands);
  for (std::size_t i = 0; i < bands.size(); ++i) {
    Band& band = workers.finished(i);
    adler = i == 0 ? band.adler
                   : adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filtered_bytes));
    if (i + 1 == bands.size())
      for (int shift = 24; shift >= 0; shift -= 8)
        band.bytes.push_back(static_cast<std::uint8_t>(adler >> shift));
    emit(band.bytes.data(), band.bytes.size());
    band.bytes.release();  // written: its memory is no longer needed
  }
}

}  // namespace clrt::image_detail
