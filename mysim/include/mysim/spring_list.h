#pragma once
#include <initializer_list>
#include <memory>
#include <vector>

#include "mysim/spring.h"

namespace mysim {

// A model's springs, shared by the copies of the model until one of them changes its list
// (copy on write). A run copies its model into the engine, the particle system and the
// reference, and the springs are most of a model (40 B a spring, 240 B a cloth particle): shared,
// a 256 x 256 cloth holds one list instead of three.
//
// Reading looks like a std::vector (and converts to one, by reference). Writing is explicit:
// push_back, reserve, clear, assignment, or edit() for the whole vector, each first copying a
// list another model still shares. There is no non-const operator[] or begin(), so a loop that
// only reads a non-const model never copies by accident.
class SpringList {
 public:
  SpringList() = default;
  SpringList(std::vector<Spring> springs)  // NOLINT(google-explicit-constructor): a list is a list
      : springs_(std::make_shared<std::vector<Spring>>(std::move(springs))) {}
  SpringList(std::initializer_list<Spring> springs) : SpringList(std::vector<Spring>(springs)) {}

  const std::vector<Spring>& all() const { return springs_ ? *springs_ : none(); }
  operator const std::vector<Spring>&() const { return all(); }  // NOLINT: read as a vector

  std::size_t size() const { return all().size(); }
  bool empty() const { return all().empty(); }
  const Spring& operator[](std::size_t k) const { return all()[k]; }
  const Spring& front() const { return all().front(); }
  const Spring& back() const { return all().back(); }
  std::vector<Spring>::const_iterator begin() const { return all().begin(); }
  std::vector<Spring>::const_iterator end() const { return all().end(); }

  // The list to change, this model's own (copied first if shared).
  std::vector<Spring>& edit() {
    if (!springs_) {
      springs_ = std::make_shared<std::vector<Spring>>();
    } else if (springs_.use_count() > 1) {
      springs_ = std::make_shared<std::vector<Spring>>(*springs_);
    }
    return *springs_;
  }
  void push_back(const Spring& spring) { edit().push_back(spring); }
  void reserve(std::size_t count) { edit().reserve(count); }
  void clear() { springs_.reset(); }

  // Whether two lists are the same storage (tests check that copies share).
  bool sharesWith(const SpringList& other) const { return springs_ && springs_ == other.springs_; }

 private:
  static const std::vector<Spring>& none() {
    static const std::vector<Spring> nothing;
    return nothing;
  }
  std::shared_ptr<std::vector<Spring>> springs_;
};

}  // namespace mysim
