#include "image/png_encoding.hpp"

#include <algorithm>
#include <iterator>

#include "image/image.hpp"

namespace clrt {
namespace {

template <typename Value>
struct Named {
  const char* name;
  Value value;
};

constexpr Named<PngFilters> kFilters[] = {
    {"none", PngFilters::None}, {"sub", PngFilters::Sub},     {"up", PngFilters::Up},
    {"average", PngFilters::Average}, {"paeth", PngFilters::Paeth},
    {"adaptive", PngFilters::Adaptive}};

constexpr Named<PngStrategy> kStrategies[] = {{"default", PngStrategy::Default},
                                              {"filtered", PngStrategy::Filtered},
                                              {"rle", PngStrategy::Rle},
                                              {"huffman", PngStrategy::HuffmanOnly}};

template <typename Value, std::size_t N>
std::string name_of(const Named<Value> (&table)[N], Value value) {
  return std::find_if(std::begin(table), std::end(table),
                      [&](const Named<Value>& entry) { return entry.value == value; })
      ->name;
}

template <typename Value, std::size_t N>
Value value_of(const Named<Value> (&table)[N], const std::string& name, const char* what) {
  const auto found = std::find_if(std::begin(table), std::end(table),
                                  [&](const Named<Value>& entry) { return name == entry.name; });
  if (found != std::end(table)) return found->value;
  std::string accepted;
  for (const Named<Value>& entry : table)
    accepted += (accepted.empty() ? "" : ", ") + std::string(entry.name);
  throw ImageError("unknown PNG " + std::string(what) + " '" + name + "' (one of " + accepted +
                   ")");
}

}  // namespace

std::string png_filters_name(PngFilters filters) { return name_of(kFilters, filters); }
std::string png_strategy_name(PngStrategy strategy) { return name_of(kStrategies, strategy); }

PngFilters png_filters_from_name(const std::string& name) {
  return value_of(kFilters, name, "filter");
}

PngStrategy png_strategy_from_name(const std::string& name) {
  return value_of(kStrategies, name, "strategy");
}

std::string describe(const PngEncoding& encoding) {
  return "level " + std::to_string(encoding.level) + ", filters " +
         png_filters_name(encoding.filters) + ", strategy " + png_strategy_name(encoding.strategy);
}

}  // namespace clrt
