// Embree throughput on the rays of a real frame: primary rays (coherent) and their mirror
// reflections (incoherent), one at a time (rtcIntersect1), in packets (rtcIntersect4/8/16) and
// in streams (rtcIntersect1M), on one thread and on all. Every packet/stream benchmark also
// reports how many rays got a different hit than rtcIntersect1 (`differs_from_single`): the
// tracer's output must not depend on how rays are batched. At one sample per pixel the two
// agree on these scenes; the 3x3-supersampled primary rays (embree/primary-spp9/...) show
// rays where they do not.
#include <benchmark/benchmark.h>

#include "bench_registry.h"
#include "bench_scenes.h"

namespace mirage::bench {

namespace {

RTCIntersectContext makeContext(bool coherent) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags =
      coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  return context;
}

void finish(benchmark::State& state, size_t rays, int threads) {
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays));
  state.counters["threads"] = threads;
  state.counters["rays"] = double(rays);  // per iteration (docs/benchmarks.md quotes it)
}

// --- single rays ---

void singleRays(benchmark::State& state, const std::vector<Ray>& rays, RTCScene scene,
                int threads) {
  for (auto _ : state) {
    forChunks(int(rays.size()), 256, threads, [&](int begin, int end) {
      RTCIntersectContext context = makeContext(false);
      for (int i = begin; i < end; ++i) {
        RTCRayHit rh = toRtcRayHit(rays[size_t(i)]);
        rtcIntersect1(scene, &context, &rh);
        benchmark::DoNotOptimize(rh);
      }
    });
  }
  finish(state, rays.size(), threads);
}

// --- packets ---

// Ray indices of the packets: primary rays in bw x bh pixel blocks inside 16x16 tiles, so a
// packet is a compact screen block; reflected rays as consecutive runs of K (neighbouring
// pixels of one tile, the tracer's order). -1 pads the last packet.
template <int K>
std::vector<int> primaryPacketOrder() {
  constexpr int bw = K == 4 ? 2 : 4, bh = K / bw;
  std::vector<int> order;
  for (int ty = 0; ty < kSize.y; ty += kTile)
    for (int tx = 0; tx < kSize.x; tx += kTile)
      for (int by = ty; by < ty + kTile; by += bh)
        for (int bx = tx; bx < tx + kTile; bx += bw)
          for (int k = 0; k < K; ++k) order.push_back((by + k / bw) * kSize.x + bx + k % bw);
  return order;
}

std::vector<int> runOrder(size_t count, int k) {
  std::vector<int> order(count);
  for (size_t i = 0; i < count; ++i) order[i] = int(i);
  while (order.size() % size_t(k) != 0) order.push_back(-1);
  return order;
}

template <int K>
void tracePacket(const std::vector<Ray>& rays, const int* index, RTCScene scene,
                 RTCIntersectContext* context, typename Packet<K>::Type& p, int* valid) {
  for (int k = 0; k < K; ++k) {
    valid[k] = index[k] >= 0 ? -1 : 0;
    setPacketLane(p, k, rays[size_t(std::max(index[k], 0))]);
  }
  Packet<K>::intersect(valid, scene, context, &p);
}

// Rays whose packet hit differs from rtcIntersect1's (one untimed pass).
template <int K>
int packetDifferences(const std::vector<Ray>& rays, const std::vector<RTCRayHit>& single,
                      const std::vector<int>& order, RTCScene scene, bool coherent) {
  RTCIntersectContext context = makeContext(coherent);
  int differ = 0;
  for (size_t b = 0; b < order.size(); b += K) {
    alignas(64) typename Packet<K>::Type p;
    alignas(64) int valid[K];
    tracePacket<K>(rays, &order[b], scene, &context, p, valid);
    for (int k = 0; k < K; ++k)
      if (order[b + size_t(k)] >= 0 &&
          !sameHit(packetLaneHit(p, k), single[size_t(order[b + size_t(k)])]))
        ++differ;
  }
  return differ;
}

template <int K>
void packetRays(benchmark::State& state, const std::vector<Ray>& rays,
                const std::vector<RTCRayHit>& single, const std::vector<int>& order, RTCScene scene,
                int threads, bool coherent) {
  const int packets = int(order.size()) / K;
  for (auto _ : state) {
    forChunks(packets, 16, threads, [&](int begin, int end) {
      RTCIntersectContext context = makeContext(coherent);
      for (int b = begin; b < end; ++b) {
        alignas(64) typename Packet<K>::Type p;
        alignas(64) int valid[K];
        tracePacket<K>(rays, &order[size_t(b) * K], scene, &context, p, valid);
        benchmark::DoNotOptimize(p);
      }
    });
  }
  finish(state, rays.size(), threads);
  state.counters["differs_from_single"] =
      packetDifferences<K>(rays, single, order, scene, coherent);
}

// --- streams: rtcIntersect1M over runs of `chunk` rays in `order` ---

void streamRays(benchmark::State& state, const std::vector<Ray>& rays,
                const std::vector<RTCRayHit>& single, const std::vector<int>& order, RTCScene scene,
                int threads, bool coherent) {
  constexpr int kChunk = 256;
  auto traceChunk = [&](int begin, int end, std::vector<RTCRayHit>& buffer) {
    RTCIntersectContext context = makeContext(coherent);
    buffer.clear();
    for (int i = begin; i < end; ++i)
      if (order[size_t(i)] >= 0) buffer.push_back(toRtcRayHit(rays[size_t(order[size_t(i)])]));
    rtcIntersect1M(scene, &context, buffer.data(), unsigned(buffer.size()), sizeof(RTCRayHit));
  };
  for (auto _ : state) {
    forChunks(int(order.size()), kChunk, threads, [&](int begin, int end) {
      thread_local std::vector<RTCRayHit> buffer;
      traceChunk(begin, end, buffer);
      benchmark::DoNotOptimize(buffer.data());
    });
  }
  finish(state, rays.size(), threads);
  int differ = 0;
  std::vector<RTCRayHit> buffer;
  for (int b = 0; b < int(order.size()); b += kChunk) {
    traceChunk(b, std::min(b + kChunk, int(order.size())), buffer);
    size_t n = 0;
    for (int i = b; i < std::min(b + kChunk, int(order.size())); ++i)
      if (order[size_t(i)] >= 0 && !sameHit(buffer[n++], single[size_t(order[size_t(i)])]))
        ++differ;
  }
  state.counters["differs_from_single"] = differ;
}

// --- supersampled primary rays: 3x3 samples per pixel in the tracer's order (tile, pixel,
// sample), generated per tile inside the timing for single rays and packets alike ---

constexpr int kGrid = 3;

void tileSamples(const View& view, int tile, std::vector<Ray>& rays) {
  const int tiles_x = kSize.x / kTile;
  const int tx = (tile % tiles_x) * kTile, ty = (tile / tiles_x) * kTile;
  rays.clear();
  for (int y = ty; y < ty + kTile; ++y)
    for (int x = tx; x < tx + kTile; ++x)
      for (int s = 0; s < kGrid * kGrid; ++s)
        rays.push_back(view.primaryRay(float(x) + (float(s % kGrid) + 0.5f) / float(kGrid),
                                       float(y) + (float(s / kGrid) + 0.5f) / float(kGrid)));
}

// Sixteen consecutive rays as one full packet.
void intersectFull16(RTCScene scene, RTCIntersectContext* context, const Ray* rays,
                     RTCRayHit16& p) {
  alignas(64) int valid[16];
  for (int k = 0; k < 16; ++k) {
    valid[k] = -1;
    setPacketLane(p, k, rays[k]);
  }
  rtcIntersect16(valid, scene, context, &p);
}

void supersampled(benchmark::State& state, const BenchScene& b, int threads, bool packets) {
  const int tiles = (kSize.x / kTile) * (kSize.y / kTile);
  constexpr int kRays = kTile * kTile * kGrid * kGrid;  // a multiple of 16
  for (auto _ : state) {
    forChunks(tiles, 1, threads, [&](int begin, int end) {
      thread_local std::vector<Ray> rays;
      RTCIntersectContext context = makeContext(packets);
      for (int tile = begin; tile < end; ++tile) {
        tileSamples(b.view, tile, rays);
        if (!packets) {
          for (const Ray& r : rays) {
            RTCRayHit rh = toRtcRayHit(r);
            rtcIntersect1(b.rtc(), &context, &rh);
            benchmark::DoNotOptimize(rh);
          }
          continue;
        }
        for (int i = 0; i < kRays; i += 16) {
          alignas(64) RTCRayHit16 p;
          intersectFull16(b.rtc(), &context, &rays[size_t(i)], p);
          benchmark::DoNotOptimize(p);
        }
      }
    });
  }
  finish(state, size_t(tiles) * kRays, threads);
  if (!packets) return;
  // Untimed: the packet answers against rtcIntersect1's, ray by ray.
  int differ = 0;
  std::vector<Ray> rays;
  RTCIntersectContext single = makeContext(false), coherent = makeContext(true);
  for (int tile = 0; tile < tiles; ++tile) {
    tileSamples(b.view, tile, rays);
    for (int i = 0; i < kRays; i += 16) {
      alignas(64) RTCRayHit16 p;
      intersectFull16(b.rtc(), &coherent, &rays[size_t(i)], p);
      for (int k = 0; k < 16; ++k) {
        RTCRayHit rh = toRtcRayHit(rays[size_t(i + k)]);
        rtcIntersect1(b.rtc(), &single, &rh);
        if (!sameHit(packetLaneHit(p, k), rh)) ++differ;
      }
    }
  }
  state.counters["differs_from_single"] = differ;
}

template <int K>
void registerPackets(const std::string& scene, int threads) {
  for (bool coherent : {true, false}) {
    const std::string flag = coherent ? "coherent" : "incoherent";
    benchmark::RegisterBenchmark(
        ("embree/primary/packet" + std::to_string(K) + "/" + flag + "/" + scene).c_str(),
        [=](benchmark::State& state) {
          const BenchScene& b = benchScene(scene);
          static const std::vector<int> order = primaryPacketOrder<K>();
          packetRays<K>(state, b.primary, b.primary_hits, order, b.rtc(), threads, coherent);
        })
        ->Apply(rayBenchmark)
        ->ArgName("threads")
        ->Arg(threads);
  }
}

}  // namespace

void registerEmbreeBenchmarks() {
  for (const std::string& scene : benchSceneNames())
    for (int threads : threadCounts()) {
      benchmark::RegisterBenchmark(("embree/primary/single/" + scene).c_str(),
                                   [=](benchmark::State& state) {
                                     const BenchScene& b = benchScene(scene);
                                     singleRays(state, b.primary, b.rtc(), threads);
                                   })
          ->Apply(rayBenchmark)
          ->ArgName("threads")
          ->Arg(threads);
      registerPackets<4>(scene, threads);
      registerPackets<8>(scene, threads);
      registerPackets<16>(scene, threads);
      benchmark::RegisterBenchmark(("embree/primary/stream1M/coherent/" + scene).c_str(),
                                   [=](benchmark::State& state) {
                                     const BenchScene& b = benchScene(scene);
                                     static const std::vector<int> order = primaryPacketOrder<16>();
                                     streamRays(state, b.primary, b.primary_hits, order, b.rtc(),
                                                threads, true);
                                   })
          ->Apply(rayBenchmark)
          ->ArgName("threads")
          ->Arg(threads);

      for (bool packets : {false, true})
        benchmark::RegisterBenchmark(
            ("embree/primary-spp9/" + std::string(packets ? "packet16/coherent/" : "single/") +
             scene)
                .c_str(),
            [=](benchmark::State& state) {
              supersampled(state, benchScene(scene), threads, packets);
            })
            ->Apply(rayBenchmark)
            ->ArgName("threads")
            ->Arg(threads);
      benchmark::RegisterBenchmark(("embree/reflected/single/" + scene).c_str(),
                                   [=](benchmark::State& state) {
                                     const BenchScene& b = benchScene(scene);
                                     singleRays(state, b.reflected, b.rtc(), threads);
                                   })
          ->Apply(rayBenchmark)
          ->ArgName("threads")
          ->Arg(threads);
      for (bool coherent : {true, false}) {
        const std::string flag = coherent ? "coherent" : "incoherent";
        benchmark::RegisterBenchmark(("embree/reflected/packet16/" + flag + "/" + scene).c_str(),
                                     [=](benchmark::State& state) {
                                       const BenchScene& b = benchScene(scene);
                                       const std::vector<int> order =
                                           runOrder(b.reflected.size(), 16);
                                       packetRays<16>(state, b.reflected, b.reflected_hits, order,
                                                      b.rtc(), threads, coherent);
                                     })
            ->Apply(rayBenchmark)
            ->ArgName("threads")
            ->Arg(threads);
        benchmark::RegisterBenchmark(
            ("embree/reflected/stream1M/" + flag + "/" + scene).c_str(),
            [=](benchmark::State& state) {
              const BenchScene& b = benchScene(scene);
              const std::vector<int> order = runOrder(b.reflected.size(), 1);
              streamRays(state, b.reflected, b.reflected_hits, order, b.rtc(), threads, coherent);
            })
            ->Apply(rayBenchmark)
            ->ArgName("threads")
            ->Arg(threads);
      }
    }
}

}  // namespace mirage::bench
