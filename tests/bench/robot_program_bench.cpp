// Reading speed of robot programs (URScript, KUKA KRL, ABB RAPID): generated programs of N
// linear motions to distinct points, as CAM post-processors write them (one point per line).

#include <string>

#include <benchmark/benchmark.h>

#include "grpvss/io/krl_file.hpp"
#include "grpvss/io/rapid_file.hpp"
#include "grpvss/io/urscript_file.hpp"

namespace {

std::string coordinate(int i, int scale) { return std::to_string((i % 1000) * scale) + "." + std::to_string(i % 7); }

void BM_ParseUrScriptLinearMotions(benchmark::State& state) {
  std::string text = "def cut():\n  set_tcp(p[0, 0, 0.1, 0, 0, 0])\n";
  for (int i = 0; i < state.range(0); ++i) {
    text += "  movel(p[0." + std::to_string(i % 1000) + ", 0.2, 0.3, 0, 3.1415, 0], a=1.2, v=0.1, r=0.001)\n";
  }
  text += "end\n";
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::io::parse_urscript(text, "cut.script"));
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(text.size()));
}
BENCHMARK(BM_ParseUrScriptLinearMotions)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

/// Points declared in the .dat (E6POS with S, T, E1..E6), motions in the .src.
void BM_ParseKrlLinearMotions(benchmark::State& state) {
  std::string src = "DEF cut()\n$TOOL = {X 0, Y 0, Z 100, A 0, B 0, C 0}\n$BASE = $NULLFRAME\n$APO.CDIS = 1\n";
  std::string dat = "DEFDAT cut\n";
  for (int i = 0; i < state.range(0); ++i) {
    const std::string name = "XP" + std::to_string(i);
    src += "LIN " + name + " C_DIS\n";
    dat += "DECL E6POS " + name + "={X " + coordinate(i, 1) + ",Y 200.0,Z 300.0,A 0.0,B 90.0,C 0.0,S 2,T 10,"
           "E1 0.0,E2 0.0,E3 0.0,E4 0.0,E5 0.0,E6 0.0}\n";
  }
  src += "END\n";
  dat += "ENDDAT\n";
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::io::parse_krl(src, "cut.src", {{"cut.dat", dat}}));
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(src.size() + dat.size()));
}
BENCHMARK(BM_ParseKrlLinearMotions)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

/// Literal robtargets in the motion statements, as RobotStudio's path export writes them.
void BM_ParseRapidLinearMotions(benchmark::State& state) {
  std::string text = "MODULE Cut\nPROC main()\n";
  for (int i = 0; i < state.range(0); ++i) {
    text += "  MoveL [[" + coordinate(i, 1) + ",200,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],"
            "v100,z1,tool0;\n";
  }
  text += "ENDPROC\nENDMODULE\n";
  for (auto _ : state) benchmark::DoNotOptimize(grpvss::io::parse_rapid(text, "cut.mod"));
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(text.size()));
}
BENCHMARK(BM_ParseRapidLinearMotions)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
