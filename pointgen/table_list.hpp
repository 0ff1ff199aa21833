#pragma once
#include "pointgen/instance_table.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace pointgen {

// Instance tables read where they are kept, any of which may be replaced by a table of its own
// (a renderer's moving sets, posed for each frame) without copying the others: ten million plants'
// tables take 560 MB. A vector of tables reads as itself, so a function taking a TableList takes
// one. The list refers to that vector, which must outlive it.
class TableList {
 public:
  TableList(const std::vector<InstanceTable>& tables) : at_(tables.size()), replaced_(tables.size()) {  // NOLINT: implicit
    for (std::size_t i = 0; i < tables.size(); ++i) at_[i] = &tables[i];
  }
  // The replacements' places would dangle in a copy.
  TableList(const TableList&) = delete;
  TableList& operator=(const TableList&) = delete;

  std::size_t size() const { return at_.size(); }
  const InstanceTable& operator[](std::size_t i) const { return *at_[i]; }
  // Table `i` is `table` from now on.
  void replace(std::size_t i, InstanceTable table) { at_[i] = &replaced_[i].emplace(std::move(table)); }

  class Iterator {
   public:
    explicit Iterator(std::vector<const InstanceTable*>::const_iterator at) : at_(at) {}
    const InstanceTable& operator*() const { return **at_; }
    Iterator& operator++() {
      ++at_;
      return *this;
    }
    bool operator!=(const Iterator& other) const { return at_ != other.at_; }

   private:
    std::vector<const InstanceTable*>::const_iterator at_;
  };
  Iterator begin() const { return Iterator(at_.begin()); }
  Iterator end() const { return Iterator(at_.end()); }

 private:
  std::vector<const InstanceTable*> at_;
  std::vector<std::optional<InstanceTable>> replaced_;  // sized once: its places stay
};

}  // namespace pointgen
