// Python bindings of the sweep: scene validation, the plan's axes and positions, and SweepJob (run on a
// thread with the GIL released; the Python side polls it, draws progress, and cancels on Ctrl-C).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/paper_table.hpp"
#include "io/run_description.hpp"
#include "io/scene_parser.hpp"
#include "job_binding.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "numpy_vector.hpp"
#include "sweep_job.hpp"

namespace py = pybind11;

namespace rotorsweep::python {

namespace {

/// The scene text (from a file when `is_path`) parsed and validated; io::SceneError otherwise.
ensemble::Scene parse_row_scene(const std::string& scene, bool is_path) {
  return is_path ? io::parse_scene_file(scene) : io::parse_scene_text(scene, "<scene>");
}

/// The plan's axes in plan order (outermost first), each with its values.
py::dict plan_axes(const ensemble::Scene& scene) {
  py::dict axes;
  axes["rows"] = scene.row_counts;
  axes["rtol"] = scene.rtol_values;
  axes["A"] = scene.A_values;
  axes["g"] = scene.g_values;
  axes["noise"] = scene.noise_values;
  axes["offset"] = scene.offset_values;
  py::list kinds;
  for (auto kind : scene.kinds) kinds.append(std::string(ensemble::kind_name(kind)));
  axes["ic"] = kinds;
  py::list replicas;
  for (int r = 0; r < scene.replicas; ++r) replicas.append(r);
  axes["replica"] = replicas;
  return axes;
}

/// The paper's table of dissipation integrals (its members and its R values).
py::dict paper_table() {
  namespace paper = ensemble::paper_table;
  py::dict table;
  table["rows"] = paper::rows;
  table["g"] = paper::g;
  table["relax_periods"] = paper::relax_periods;
  table["average_periods"] = paper::average_periods;
  py::list A, ic, R, cp;
  for (const auto& entry : paper::entries) {
    A.append(entry.A);
    ic.append(std::string(ensemble::kind_name(entry.kind)));
    R.append(entry.paper_R);
    cp.append(entry.cp);
  }
  table["A"] = A;
  table["ic"] = ic;
  table["R"] = R;
  table["cp"] = cp;
  return table;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "plan_axes", [](const std::string& scene, bool is_path) { return plan_axes(parse_row_scene(scene, is_path)); },
      py::arg("scene"), py::arg("is_path") = false,
      "The member plan's axes of a scene (TOML text, or a path with is_path): a dict from axis name "
      "to its values, outermost first; raises ValueError naming a bad key.");
  m.def(
      "plan_positions",
      [](const std::string& scene, bool is_path) {
        const auto parsed = parse_row_scene(scene, is_path);
        const ensemble::MemberPlan plan(parsed);
        const auto sizes = parsed.axis_sizes();
        std::vector<std::int64_t> flat(plan.size());
        for (std::size_t i = 0; i < plan.size(); ++i) {
          const auto at = plan.axis_position(i);
          std::size_t f = 0;
          for (std::size_t a = 0; a < sizes.size(); ++a) f = f * sizes[a] + at[a];
          flat[i] = std::int64_t(f);
        }
        return to_numpy(std::move(flat));
      },
      py::arg("scene"), py::arg("is_path") = false,
      "Each member's place on the grid of plan_axes (C-order flat index): initial.noise and offset "
      "do not multiply random and exact starts, which sit at their first values.");
  m.def(
      "scene_info",
      [](const std::string& scene, bool is_path) {
        const auto parsed = parse_row_scene(scene, is_path);
        py::dict info;
        info["text"] = parsed.text;
        info["output_path"] = parsed.output_path;
        info["members"] = parsed.member_count();
        return info;
      },
      py::arg("scene"), py::arg("is_path") = false,
      "The validated scene: its text, output.path ('' when not given) and member count.");
  m.def(
      "run_description",
      [](const std::string& scene, bool is_path, int threads) {
        return io::run_description(parse_row_scene(scene, is_path), is_path ? scene : std::string("<python>"),
                                   parse_row_scene(scene, is_path).member_count(),
                                   ensemble::thread_count(threads, "threads"), ensemble::instruction_set().lanes);
      },
      py::arg("scene"), py::arg("is_path"), py::arg("threads"),
      "The lines `rotorsweep run` prints before it starts (threads 0: the default count).");
  m.attr("paper_table") = paper_table();
  m.attr("lane_width") = kernels::lane_width<kernels::simd_lane>;
  m.attr("instruction_set") = ensemble::instruction_set().name;
  py::list steppers;
  for (auto name : kernels::stepper_names) steppers.append(std::string(name));
  m.attr("steppers") = steppers;
  m.attr("default_stepper") = std::string(kernels::default_stepper_name);

  py::class_<SweepJob> sweep_job(m, "SweepJob",
                                 "A sweep on its own thread; poll wait(), read done/total/periods, cancel().");
  bind_job_polling(sweep_job)
      .def(py::init([](const std::string& scene, bool is_path, int threads, const std::string& output,
                       bool force, const std::string& version, const std::string& revision) {
             const std::string source = is_path ? scene : std::string("<python>");
             return std::make_unique<SweepJob>(
                 parse_row_scene(scene, is_path), threads, output, force,
                 io::Provenance{source, version, revision, ensemble::device_label(parse_row_scene(scene, is_path)),
                                ensemble::instruction_set().name});
           }),
           py::arg("scene"), py::arg("is_path"), py::arg("threads"), py::arg("output"), py::arg("force"),
           py::arg("version"), py::arg("revision"))
      .def(
          "take_image",
          [](SweepJob& job) {
            const auto image = job.take_image();
            return py::bytes(reinterpret_cast<const char*>(image.data()), image.size());
          },
          "The result as HDF5 file bytes (b'' when it went to the output path); raises the sweep's error.");
}

}  // namespace rotorsweep::python
