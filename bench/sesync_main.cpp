// SE-Sync's own C++ (Rosen et al., IJRR 2019; its git mirror) on one .g2o file, for
// bench/poses.mjs: its example program's settings (chordal start, the simplified formulation,
// every other option its default) on one thread, like kli in wasm. Built by bench/sesync.mjs in
// place of SE-Sync's examples/main.cpp.
//
// argv: the .g2o file, the JSON file to write. The JSON: SE-Sync's own time (its
// total_computation_time, the file's reading left out as kli's time leaves out readG2o), its
// status (0: GlobalOpt, certified at its own eigenvalue tolerance), the staircase's last rank,
// its rounded cost F(xhat) and suboptimality bound, and its poses (rotations row by row,
// translations), which the bench evaluates in the reference's cost itself.

#include "SESync/SESync.h"
#include "SESync/SESync_utils.h"

#include <cstdio>
#include <fstream>
#include <iostream>

using namespace SESync;

int main(int argc, char **argv) {
  if (argc != 3) {
    std::cerr << "usage: " << argv[0] << " graph.g2o out.json" << std::endl;
    return 2;
  }
  size_t n = 0;
  measurements_t measurements = read_g2o_file(argv[1], n);
  if (measurements.empty()) {
    std::cerr << "no measurements read from " << argv[1] << std::endl;
    return 1;
  }
  SESyncOpts opts;
  opts.initialization = Initialization::Chordal;
  opts.formulation = Formulation::Simplified;
  opts.num_threads = 1;
  SESyncResult result = SESync::SESync(measurements, opts);

  const size_t d = result.xhat.rows();
  std::ofstream out(argv[2]);
  out.precision(17);
  out << "{\"seconds\":" << result.total_computation_time << ",\"status\":" << int(result.status)
      << ",\"rank\":" << result.Yopt.rows() << ",\"cost\":" << result.Fxhat
      << ",\"suboptimality\":" << result.suboptimality_bound << ",\"dimension\":" << d
      << ",\"rotations\":[";
  // xhat = [t | R]: the translations in its first n columns, then R_i in columns n + d i.
  for (size_t i = 0; i < n; i++)
    for (size_t a = 0; a < d; a++)
      for (size_t b = 0; b < d; b++)
        out << (i + a + b ? "," : "") << result.xhat(a, n + d * i + b);
  out << "],\"translations\":[";
  for (size_t i = 0; i < n; i++)
    for (size_t a = 0; a < d; a++)
      out << (i + a ? "," : "") << result.xhat(a, i);
  out << "]}" << std::endl;
  return out.good() ? 0 : 1;
}
