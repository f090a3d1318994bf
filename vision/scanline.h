#pragma once

namespace houghloc {

/// One scanline: n pixels of a run (BgrRun read in place, DecodedRun from a decoding reader;
/// pixel_access.h); (u0, v0) + i * (du, dv) is pixel i's position.
template <typename Run>
struct Scanline {
  Run run;
  int n;
  int u0, v0, du, dv;
  const unsigned char* at(int i) const { return run.at(i); }
  int luma(int i) const { return run.luma(i); }
};

template <typename Run>
Scanline<Run> scanline(const Run& run, int n, int u0, int v0, int du, int dv) {
  return {run, n, u0, v0, du, dv};
}

/// Where the luma falls below `level` walking from `peak` in direction dir (+1 or -1), sub-pixel
/// (linear between the last pixel at or above it and the first below). At the scanline's end:
/// the last pixel's index.
template <typename Run>
float levelCrossing(const Scanline<Run>& line, int peak, int dir, float level) {
  int k = peak;
  while (k + dir >= 0 && k + dir < line.n && line.luma(k + dir) >= level) k += dir;
  if (k + dir < 0 || k + dir >= line.n) return static_cast<float>(k);
  const float inside = static_cast<float>(line.luma(k)),
              outside = static_cast<float>(line.luma(k + dir));
  const float t = inside > outside ? (inside - level) / (inside - outside) : 0.5f;
  return k + dir * t;
}

}  // namespace houghloc
