#pragma once
// What a check of a model or run against its limits refuses: every check (run limits, model
// scales, self-collision, the start state) answers in this one form, so a scene's reader can name
// the field.
#include <string>

namespace mysim {

// Which field breaks a limit, and how.
struct LimitError {
  std::string field;  // "integrator.dt", "integrator.duration", "output.sample_interval", "system"
  std::string message;
};

}  // namespace mysim
