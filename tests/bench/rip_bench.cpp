// tests/bench/rip_bench.cpp: micro-benchmarks of the RIP's hot loops (per row of a 1.6 m wide roll at
// 600 dpi): colour tables, screening, PackBits, the stand-in and design renderers. Figures in pixels per second.
#include <benchmark/benchmark.h>

#include <random>

#include "device/swath/packbits.h"
#include "host/bench/bench_marker.h"
#include "rip/colour/ink_converter.h"
#include "rip/render/marker_source.h"
#include "rip/screen/screen.h"

namespace tp::rip {
namespace {

constexpr int kRowPx = 37795;  ///< 1.6 m at 600 dpi

/// One rendered row of the benchmark design (photographic statistics, not a flat colour).
std::vector<geometry::Rgba8> design_row(int row) {
  static const BenchJob job = make_textured_bench_job(1600);
  static const auto src = MarkerSource::create(job.block, *job.renderer, 600, 600);
  std::vector<geometry::Rgba8> px(static_cast<size_t>(kRowPx) * kRenderTileRows);
  (*src)->render_rows(row / kRenderTileRows * kRenderTileRows, kRenderTileRows, px.data(), kRowPx);
  px.resize(kRowPx);
  return px;
}

void BM_ColourRow(benchmark::State& state) {
  auto conv = InkConverter::create(InkConverterSettings{});
  if (!conv) {
    state.SkipWithError(conv.error().message.c_str());
    return;
  }
  const auto row = design_row(1000);
  std::vector<std::vector<std::uint8_t>> planes(4, std::vector<std::uint8_t>(kRowPx));
  std::uint8_t* out[4] = {planes[0].data(), planes[1].data(), planes[2].data(), planes[3].data()};
  for (auto _ : state) {
    conv->convert_row(row.data(), kRowPx, out);
    benchmark::DoNotOptimize(planes[0].data());
  }
  state.SetItemsProcessed(state.iterations() * kRowPx);
}
BENCHMARK(BM_ColourRow);

void BM_ScreenRow(benchmark::State& state) {
  ScreenSetup setup{static_cast<ScreenKind>(state.range(0)), 4, 4, 2, kRowPx};
  auto screen = make_screen(setup);
  std::vector<std::uint8_t> contone(static_cast<size_t>(padded_width(kRowPx)), 0), packed(static_cast<size_t>(packed_row_bytes(setup)));
  std::mt19937 rng(1);
  for (int x = 0; x < kRowPx; ++x) contone[static_cast<size_t>(x)] = static_cast<std::uint8_t>(128 + 100 * std::sin(x * 0.001) + rng() % 16);
  std::int64_t y = 0;
  for (auto _ : state) {
    (*screen)->screen_row(0, y++, contone.data(), packed.data());
    benchmark::DoNotOptimize(packed.data());
  }
  state.SetItemsProcessed(state.iterations() * kRowPx);
}
BENCHMARK(BM_ScreenRow)->Arg(static_cast<int>(ScreenKind::kBlueNoise))->Arg(static_cast<int>(ScreenKind::kErrorDiffusion));

void BM_PackBitsScreenedRow(benchmark::State& state) {
  ScreenSetup setup{ScreenKind::kBlueNoise, 1, 4, 2, kRowPx};
  auto screen = make_screen(setup);
  std::vector<std::uint8_t> contone(static_cast<size_t>(padded_width(kRowPx)), 0), packed(static_cast<size_t>(packed_row_bytes(setup)));
  for (int x = 0; x < kRowPx; ++x) contone[static_cast<size_t>(x)] = static_cast<std::uint8_t>(state.range(0));
  (*screen)->screen_row(0, 0, contone.data(), packed.data());
  std::vector<std::uint8_t> out(device::packbits_max_size(packed.size()));
  size_t n = 0;
  for (auto _ : state) {
    n = device::packbits_encode(packed, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(packed.size()));
  state.counters["ratio"] = static_cast<double>(packed.size()) / static_cast<double>(n);
}
BENCHMARK(BM_PackBitsScreenedRow)->Arg(0)->Arg(40)->Arg(128)->Arg(255);

void BM_RenderTile(benchmark::State& state) {
  const BenchJob job = make_textured_bench_job(1600);
  auto src = MarkerSource::create(job.block, *job.renderer, 600, 600);
  std::vector<geometry::Rgba8> px(static_cast<size_t>(kRowPx) * kRenderTileRows);
  std::int64_t y = 0;
  for (auto _ : state) {
    (*src)->render_rows(y, kRenderTileRows, px.data(), kRowPx);
    y = (y + kRenderTileRows) % 10000;
    benchmark::DoNotOptimize(px.data());
  }
  state.SetItemsProcessed(state.iterations() * kRowPx * kRenderTileRows);
}
BENCHMARK(BM_RenderTile);

/// The design renderer on the full-coverage panels (two planar projections, one repeated, one a
/// rotated motif at 60 % opacity): one tile of the roll width per iteration.
void BM_RenderPanelTile(benchmark::State& state) {
  auto job = make_panel_bench_job(1600, 1);
  if (!job) {
    state.SkipWithError(job.error().message.c_str());
    return;
  }
  auto src = MarkerSource::create(job->block, *job->renderer, 600, 600);
  std::vector<geometry::Rgba8> px(static_cast<size_t>(kRowPx) * kRenderTileRows);
  std::int64_t y = 0;
  for (auto _ : state) {
    std::fill(px.begin(), px.end(), geometry::Rgba8{});
    (*src)->render_rows(y, kRenderTileRows, px.data(), kRowPx);
    y = (y + 7 * kRenderTileRows) % 23000;
    benchmark::DoNotOptimize(px.data());
  }
  state.SetItemsProcessed(state.iterations() * kRowPx * kRenderTileRows);
}
BENCHMARK(BM_RenderPanelTile)->Unit(benchmark::kMillisecond);

/// ctest's smoke run: cheap, checks the executable links and runs.
void BM_Smoke(benchmark::State& state) {
  std::vector<std::uint8_t> row(4096, 0), out(device::packbits_max_size(4096));
  for (auto _ : state) benchmark::DoNotOptimize(device::packbits_encode(row, out.data()));
}
BENCHMARK(BM_Smoke);

}  // namespace
}  // namespace tp::rip

BENCHMARK_MAIN();
