#pragma once
// Shadow rays gathered into Embree ray streams: the one stream-and-flush loop that rt_shadows'
// rows (traceShadowTile), traceShadowRays' tasks, the Whitted tiles and the path tracer's levels
// share.
#include <cstddef>
#include <utility>

#include "engine/rt/rt_scene.h"

namespace diptych {

// Rays per stream: Embree's own tutorials trace 8x8 tiles; 256 rays amortise the stream setup
// further and still fit a worker's stack.
inline constexpr std::size_t kOcclusionStreamRays = 256;

// Rays are added one at a time with an owner (whatever the caller maps an answer back to: a
// counter's index, a light term). Every kRays rays, and at flush(), they are traced as one
// stream (RtScene::occludedTile: rtcOccluded1M, ray by ray on alpha-filtered scenes) and
// answer(owner, visible) is called for each, in the order they were added. An inactive ray
// (tnear > tfar: a light that casts no shadows, a degenerate segment) is answered visible, as
// lightVisibility counts it. The caller flushes before it reads its answers.
// The buffers are members (about 13 KB at 256 rays; an RTCRay is 48 bytes): one stream per
// task on a worker's stack, no allocation per ray or per tile. `answer` is a template
// parameter, inlined into the flush loop: no std::function call per ray.
template <class Owner, class Answer>
class OcclusionStream {
 public:
  static constexpr std::size_t kRays = kOcclusionStreamRays;

  // coherent: neighbouring rays are similar (a row of pixels toward one light); false for rays
  // from scattered points (RtScene::occludedTile).
  OcclusionStream(const RtScene& rt, bool coherent, Answer answer)
      : rt_(rt), coherent_(coherent), answer_(std::move(answer)) {}
  OcclusionStream(const OcclusionStream&) = delete;
  OcclusionStream& operator=(const OcclusionStream&) = delete;

  void add(const OcclusionRay& ray, Owner owner) {
    // In place (rt_scene.h): a copied temporary stalled on store forwarding, about a fifth of
    // the Whitted tiles' own time (perf annotate).
    setEmbreeRay(rays_[filled_], ray);
    owners_[filled_] = owner;
    active_[filled_] = ray.tnear <= ray.tfar;
    if (++filled_ == kRays) flush();
  }

  void flush() {
    if (filled_ == 0) return;
    rt_.occludedTile({rays_, filled_}, coherent_);
    // Embree sets an occluded ray's tfar to -inf; an inactive ray keeps its own, maybe negative.
    for (std::size_t i = 0; i < filled_; ++i)
      answer_(owners_[i], !(active_[i] && rays_[i].tfar < 0.f));
    filled_ = 0;
  }

 private:
  const RtScene& rt_;
  bool coherent_;
  Answer answer_;
  RTCRay rays_[kRays];  // RTC_ALIGN(16), as rtcOccluded1M requires
  Owner owners_[kRays];
  bool active_[kRays];
  std::size_t filled_ = 0;
};

}  // namespace diptych
