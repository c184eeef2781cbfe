#pragma once
// Exports a compiled graph (and, when given, its measured timings) as Graphviz DOT or JSON:
// passes, resources, edges, lifetimes, culled passes with reasons, pooled memory with and
// without reuse, and per-node timings (median over the measured frames).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"

namespace diptych {

// {median, min, max, samples} of per-frame samples in ms.
nlohmann::json timingStatsJson(const std::vector<double>& samples);

nlohmann::json graphToJson(const CompiledGraph& graph,
                           const std::vector<NodeTiming>* timings = nullptr);
std::string graphToDot(const CompiledGraph& graph,
                       const std::vector<NodeTiming>* timings = nullptr);

// A run's first frame against a steady one (GraphExecutor::MeasuredRun): {wall_ms, one_time_ms,
// steady_ms, unrecorded_ms, first_use_ms: {node: ms}} (nodes above kFirstUseShownMs only), and
// the same as one line for a terminal.
constexpr double kFirstUseShownMs = 1.0;
nlohmann::json firstFrameJson(const CompiledGraph& graph, const GraphExecutor::MeasuredRun& run);
std::string firstFrameLine(const CompiledGraph& graph, const GraphExecutor::MeasuredRun& run);

}  // namespace diptych
