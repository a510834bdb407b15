#include "gpu/frame_timer.h"

#include "core/check.h"
#include "core/choices.h"
#include "core/error.h"

#include <utility>

namespace mirage::gpu {

const char* partName(Part part) {
  static constexpr Choice<Part> kParts[] = {
      {"update", Part::kUpdate}, {"direct", Part::kDirect}, {"reflect", Part::kReflect}};
  return choiceName<Part>(kParts, part);
}

Clock defaultClock(bool software_renderer) {
  return software_renderer ? Clock::kWall : Clock::kGpu;
}

const char* clockName(Clock clock) {
  return clock == Clock::kWall ? "wall+glFinish" : "gl-timestamp";
}

void FrameTimer::mark(int part) {
  Mark m{part, 0.0, 0};
  if (clock_ == Clock::kWall) {
    glFinish();
    m.wall_ms = stopwatch_.ms();
  } else {
    GLuint id = 0;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
    } else {
      glGenQueries(1, &id);
      queries_.emplace_back(id);
    }
    glQueryCounter(id, GL_TIMESTAMP);
    m.query = id;
  }
  current_.marks.push_back(m);
}

void FrameTimer::beginFrame() {
  MIRAGE_CHECK(current_.marks.empty());  // beginFrame inside a frame
  if (clock_ == Clock::kGpu) harvest(false);
  mark(-1);
}

void FrameTimer::beginPart(Part part) {
  MIRAGE_CHECK(!current_.marks.empty());  // beginPart outside a frame
  mark(int(part));
}

void FrameTimer::endFrame() {
  MIRAGE_CHECK(!current_.marks.empty());  // endFrame outside a frame
  mark(kPartCount);
  pending_.push_back(std::move(current_));
  current_ = {};
}

void FrameTimer::shift(Part from, Part to, double ms) {
  MIRAGE_CHECK(!current_.marks.empty());  // shift outside a frame
  current_.shift_ms[size_t(from)] -= ms;
  current_.shift_ms[size_t(to)] += ms;
}

FrameTimes FrameTimer::resolve(const Frame& frame) const {
  const std::vector<Mark>& marks = frame.marks;
  std::vector<double> t(marks.size());
  for (size_t i = 0; i < marks.size(); ++i) {
    if (clock_ == Clock::kWall) {
      t[i] = marks[i].wall_ms;
    } else {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(marks[i].query, GL_QUERY_RESULT, &ns);
      t[i] = double(ns) * 1e-6;
    }
  }
  FrameTimes ft;
  ft.total_ms = t.back() - t.front();
  // Each interval belongs to the part whose mark opened it.
  for (size_t i = 1; i < marks.size(); ++i) {
    int part = marks[i - 1].part;
    if (part >= 0 && part < kPartCount) ft.part_ms[size_t(part)] += t[i] - t[i - 1];
  }
  for (int p = 0; p < kPartCount; ++p) ft.part_ms[size_t(p)] += frame.shift_ms[size_t(p)];
  return ft;
}

void FrameTimer::harvest(bool wait) {
  size_t resolved = 0;
  for (; resolved < pending_.size(); ++resolved) {
    const Frame& frame = pending_[resolved];
    if (!wait && clock_ == Clock::kGpu) {
      // The GPU answers a frame's queries in order: its last mark is its last answer.
      GLuint available = GL_FALSE;
      glGetQueryObjectuiv(frame.marks.back().query, GL_QUERY_RESULT_AVAILABLE, &available);
      if (available != GL_TRUE) break;
    }
    done_.push_back(resolve(frame));
    if (clock_ == Clock::kGpu)
      for (const Mark& m : frame.marks) free_.push_back(m.query);
  }
  pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(resolved));
}

std::vector<FrameTimes> FrameTimer::takeResults() {
  harvest(true);
  return std::exchange(done_, {});
}

}  // namespace mirage::gpu
