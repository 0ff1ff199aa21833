#pragma once
#include "app/gl/gl_objects.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace ecoview::gl {

// The GPU time of a frame's stages: a timestamp where each stage ends, read when asked, so that
// nothing waits for the GPU in the middle of a frame. A stage may end several times a frame (each
// distance band's passes); its times add up. Stage names are string literals.
class GpuStages {
 public:
  // A new frame: its first stage starts here.
  void start() {
    names_.clear();
    stamp(0);
  }
  // The commands since start() or the last end() belong to `stage`.
  void end(const char* stage) {
    if (stamps_.empty()) return;
    names_.push_back(stage);
    stamp(names_.size());
  }
  // Milliseconds by stage, in the order each first ended; waits for the last timestamp.
  std::vector<std::pair<std::string, double>> ms() const {
    std::vector<std::pair<std::string, double>> stages;
    GLuint64 last = 0;
    if (!names_.empty()) glGetQueryObjectui64v(stamps_[0].name(), GL_QUERY_RESULT, &last);
    for (std::size_t i = 0; i < names_.size(); ++i) {
      GLuint64 now = 0;
      glGetQueryObjectui64v(stamps_[i + 1].name(), GL_QUERY_RESULT, &now);
      const double ms = now > last ? static_cast<double>(now - last) * 1e-6 : 0.0;
      last = now;
      auto same = std::find_if(stages.begin(), stages.end(), [&](const auto& s) { return s.first == names_[i]; });
      if (same == stages.end()) stages.emplace_back(names_[i], ms);
      else same->second += ms;
    }
    return stages;
  }

 private:
  void stamp(std::size_t i) {
    if (i == stamps_.size()) stamps_.emplace_back(GL_TIMESTAMP);
    glQueryCounter(stamps_[i].name(), GL_TIMESTAMP);
  }

  std::vector<Query> stamps_;       // stamps_[0] where the frame starts, stamps_[i + 1] where names_[i] ends
  std::vector<const char*> names_;
};

}  // namespace ecoview::gl
