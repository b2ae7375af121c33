// Compactor (src/render/compactor.cpp with kernels/compact.cl) against the host's stable filter:
// the kept records in their original order, the count of flagged records, and nothing written
// past the capacity (a guard pattern after it must survive).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "render/compactor.hpp"

using namespace clrt;

namespace {

constexpr std::uint32_t kGuard = 0xdeadbeefu;
constexpr std::size_t kGuardRecords = 5;
constexpr std::size_t kMaxSlots = 70001;

// Word w of record i: distinct for every (i, w), so any misplaced word shows.
std::vector<std::uint32_t> numbered_records(std::size_t slots, std::size_t words) {
  std::vector<std::uint32_t> data(slots * words);
  for (std::size_t i = 0; i < slots; ++i)
    for (std::size_t w = 0; w < words; ++w)
      data[i * words + w] = static_cast<std::uint32_t>(i * 1000003u + w * 7919u + 1u);
  return data;
}

enum class Mask { Random, Sparse, All, None };

std::vector<std::uint32_t> make_flags(std::size_t slots, Mask mask, std::mt19937& rng) {
  std::vector<std::uint32_t> flags(slots);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (auto& f : flags) {
    switch (mask) {
      case Mask::Random: f = uniform(rng) < 0.5; break;
      case Mask::Sparse: f = uniform(rng) < 0.05; break;
      case Mask::All: f = 1; break;
      case Mask::None: f = 0; break;
    }
  }
  return flags;
}

// The host's stable filter.
std::vector<std::uint32_t> kept_records(const std::vector<std::uint32_t>& records,
                                        const std::vector<std::uint32_t>& flags, std::size_t words) {
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) kept.insert(kept.end(), records.begin() + i * words, records.begin() + (i + 1) * words);
  return kept;
}

// Kept to the end of the process, as the fixture keeps its context: released by a static
// destructor after the implementation's own state is gone, its buffers corrupted Oclgrind's heap.
Compactor& compactor() {
  static Compactor& c = *new Compactor(test::device(), test::renderer_program(), kMaxSlots);
  return c;
}

// A record of `Words` uint4 words, as the compaction moves them.
template <std::size_t Words>
struct Record {
  cl_uint4 word[Words];
};

template <class R>
std::uint32_t compact_as(const Global<cl_uint>& in, const Global<cl_uint>& flags,
                         std::size_t slots, const Global<cl_uint>& out, std::size_t capacity) {
  static Launcher& launcher = *new Launcher(test::device(), test::local_size(), false);
  compactor().enqueue(launcher, Global<R>(in.buffer), flags, slots, Global<R>(out.buffer),
                      capacity, 0);
  return compactor().read_total();
}

std::uint32_t compact(const Global<cl_uint>& in, const Global<cl_uint>& flags, std::size_t slots,
                      std::size_t record_bytes, const Global<cl_uint>& out, std::size_t capacity) {
  switch (record_bytes) {
    case 16: return compact_as<Record<1>>(in, flags, slots, out, capacity);
    case 48: return compact_as<Record<3>>(in, flags, slots, out, capacity);
    case 64: return compact_as<Record<4>>(in, flags, slots, out, capacity);
  }
  throw std::logic_error("no record type of " + std::to_string(record_bytes) + " bytes");
}

// The output's capacity, from the number of records the host keeps.
using Capacity = std::function<std::size_t(std::size_t kept)>;
const Capacity kExact = [](std::size_t kept) { return kept; };

// Compacts into an output of `capacity` records followed by guard records; checks the count,
// the kept records in order and that every word after them is still the guard.
void check_compaction(std::size_t slots, std::size_t record_bytes, Mask mask,
                      const Capacity& capacity_of, std::mt19937& rng) {
  const std::size_t words = record_bytes / 4;
  const std::vector<std::uint32_t> records = numbered_records(slots, words);
  const std::vector<std::uint32_t> flags = make_flags(slots, mask, rng);
  const std::vector<std::uint32_t> expected = kept_records(records, flags, words);
  const std::size_t kept = expected.size() / words;
  const std::size_t capacity = capacity_of(kept);
  INFO("kept " << kept << ", capacity " << capacity);

  const std::size_t out_words = (capacity + kGuardRecords) * words;
  const Global<cl_uint> in =
      test::upload(records.empty() ? std::vector<cl_uint>(words) : records);
  const Global<cl_uint> flag_buffer =
      test::upload(flags.empty() ? std::vector<cl_uint>(1) : flags);
  const Global<cl_uint> out = test::upload(std::vector<cl_uint>(out_words, kGuard));
  const std::uint32_t count = compact(in, flag_buffer, slots, record_bytes, out, capacity);
  const std::vector<std::uint32_t> result = test::download(out, out_words);

  CHECK(count == kept);
  const std::size_t written = std::min(kept, capacity) * words;
  CHECK(std::equal(expected.begin(), expected.begin() + static_cast<std::ptrdiff_t>(written),
                   result.begin()));
  CHECK(std::all_of(result.begin() + static_cast<std::ptrdiff_t>(written), result.end(),
                    [](std::uint32_t w) { return w == kGuard; }));
}

const std::vector<std::size_t> kSizes = {1, 2, 63, 64, 65, 255, 256, 257, 1000, 4097, 16385, kMaxSlots};

}  // namespace

TEST_CASE("compaction keeps the flagged records in order", "[compact]") {
  std::mt19937 rng(20071101);
  for (std::size_t record_bytes : {16, 48, 64}) {
    for (std::size_t slots : kSizes) {
      for (Mask mask : {Mask::Random, Mask::Sparse, Mask::All, Mask::None}) {
        INFO("record bytes " << record_bytes << ", slots " << slots << ", mask "
                             << static_cast<int>(mask));
        check_compaction(slots, record_bytes, mask, kExact, rng);
      }
    }
  }
}

TEST_CASE("compaction of zero slots returns 0 and writes nothing", "[compact]") {
  std::mt19937 rng(1);
  check_compaction(0, 64, Mask::All, [](std::size_t) { return 3; }, rng);
}

TEST_CASE("compaction past the capacity counts everything but writes only the capacity",
          "[compact]") {
  std::mt19937 rng(575);
  for (std::size_t record_bytes : {16, 48, 64}) {
    for (std::size_t slots : {65, 1000, 16385}) {
      for (Mask mask : {Mask::Random, Mask::All}) {
        // No room, a third of the room, one record short.
        const std::vector<Capacity> capacities = {
            [](std::size_t) { return std::size_t{0}; }, [](std::size_t kept) { return kept / 3; },
            [](std::size_t kept) { return kept - 1; }};
        for (const Capacity& capacity : capacities) {
          INFO("record bytes " << record_bytes << ", slots " << slots);
          check_compaction(slots, record_bytes, mask, capacity, rng);
        }
      }
    }
  }
}
