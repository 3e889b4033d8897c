// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the untangler: every case with every solver, each run in a
// forked child process so that peak memory is per run, and a crash or a hang
// of one run does not stop the others.  Prints a markdown table and, per pair
// of solvers, how many cases each solved and the median ratio of their times.
//
//   benchmark_untangle [--solver auto,lbfgs] [--time-limit SECONDS] [--threads N] [--refine] [--markdown FILE] CASE...
//
// Run with --help for the forms of CASE.

#include "cases.h"
#include "memory_reuse.h"
#include "thread_limit.h"
#include "untangle_mesh_file.h"

#include <CGAL/Mesh_untangling/IO/handles.h>
#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>


#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
namespace MU = CGAL::Mesh_untangling;
using namespace Mesh_untangling_tools;

namespace {

const char* const usage_text =
  "usage: benchmark_untangle [--solver auto,lbfgs] [--time-limit SECONDS] [--threads N] [--refine] [--markdown FILE] CASE...\n"
  "\n"
  "Runs the untangler on every CASE with every solver, each run in its own process,\n"
  "and prints a markdown table (stdout, and FILE with --markdown).\n"
  "\n"
  "  --solver LIST        comma-separated solvers among auto (the default solver), newton, lbfgs\n"
  "                       (the published scheme); default: auto,lbfgs\n"
  "  --time-limit SECONDS time limit of one run (default: 120), passed to the untangler;\n"
  "                       a run still going 30 s past it is killed (SIGKILL)\n"
  "  --threads N          at most N threads in the untangler's parallel loops (TBB global_control;\n"
  "                       default: TBB's choice); results do not depend on N, the hash column shows it\n"
  "  --refine             add the columns of local refinement (Mesh_untangling::parameters::refinement):\n"
  "                       a run the fixed connectivity did not solve is run again with refinement\n"
  "                       (its own process and time limit); a solved one needs none (0 vertices added)\n"
  "  --markdown FILE      also write the table and the summary to FILE\n"
  "\n"
  "A CASE is one of:\n"
  "  FILE.input                       Du et al. format: rest, map and handles (fixed vertices)\n"
  "  FOLDER/                          CuboidBlocks layout: object.vtk (rest), parameter.vtk (map),\n"
  "                                   handles.txt (fixed vertex ids)\n"
  "  REST:INIT                        two mesh files with the same elements (rest, tangled map);\n"
  "                                   all boundary vertices fixed\n"
  "  generated:square:N:AMPLITUDE:SEED  N x N grid of the unit square, interior vertices moved\n"
  "  generated:cube:N:AMPLITUDE:SEED    by up to AMPLITUDE cells (random, SEED); boundary fixed\n"
  "  all-fixed-boundary:DATA_DIR      every fixed-boundary case of the shared data: the LIM\n"
  "                                   armadillo, four tlc-format files, every cuboidblocks folder\n";

struct Usage_error
{
  std::string message;
};

// ---------------------------------------------------------------------------
// The child: loads the case, untangles it, and sends "key value" lines.

void write_all(int fd, const std::string& text)
{
  const char* data = text.data();
  std::size_t left = text.size();
  while(left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if(written < 0) {
      if(errno == EINTR) continue;
      return;   // the parent is gone: nothing to report to
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

std::string one_line(std::string text)
{
  for(char& ch : text)
    if(ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
  return text;
}

std::string short_status(MU::Untangling_status status)
{
  switch(status) {
    case MU::Untangling_status::SUCCESS: return "success";
    case MU::Untangling_status::INVERTED_ELEMENTS_LEFT: return "inverted elements left";
    case MU::Untangling_status::COVERINGS_LEFT: return "coverings left";
    case MU::Untangling_status::TIME_LIMIT_REACHED: return "time limit reached";
    case MU::Untangling_status::STOPPED_BY_CALLBACK: return "stopped by callback";
    case MU::Untangling_status::NUMERICAL_FAILURE: return "numerical failure";
    case MU::Untangling_status::INVALID_INPUT: return "invalid input";
    case MU::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT: return "input defects left";
    case MU::Untangling_status::CANCELLED: return "cancelled";
  }
  return "unknown status";
}

/// FNV-1a over the bytes of the map's coordinates: equal hashes mean
/// (barring collisions) bitwise equal results.
std::string format_energy(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string positions_hash(const Mesh_file& mesh)
{
  std::uint64_t h = 14695981039346656037ull;
  for(const auto& p : mesh.map)
    for(double c : p) {
      unsigned char bytes[sizeof(double)];
      std::memcpy(bytes, &c, sizeof c);
      for(unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

void child_run(int fd, const Case_spec& c, const std::string& solver, double time_limit, int threads, bool refine)
{
  const Thread_limit limit(threads);
  auto send = [fd](const std::string& key, const std::string& value) { write_all(fd, key + "\t" + value + "\n"); };
  try {
    Problem p = load(c);
    std::size_t fixed = 0;
    for(bool f : p.is_fixed) fixed += f;
    send("vertices", std::to_string(p.mesh.number_of_vertices()));
    send("elements", std::to_string(p.mesh.simplices.size()));
    send("fixed", std::to_string(fixed));
    const Verdict before = check_mesh_file(p.mesh, p.is_fixed);
    send("inverted_before", std::to_string(before.inverted));
    send("input_defects", std::to_string(before.input_defects));

    Run_options options;
    options.solver = *CGAL::Mesh_untangling::solver_from_string(solver);
    options.max_seconds = time_limit;
    options.refinement = refine;
    const auto start = std::chrono::steady_clock::now();
    const Untangling_result result = untangle_mesh_file(p.mesh, p.is_fixed, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    send("seconds", std::to_string(seconds));
    send("solver", one_line(result.solver));
    send("eps_steps", std::to_string(result.outer_iterations));
    send("evaluations", std::to_string(result.energy_evaluations));
    send("iterations", std::to_string(result.inner_iterations));
    send("energy", format_energy(result.final_energy));
    send("final_eps", format_energy(result.final_epsilon));
    send("status", short_status(result.status));
    send("vertices_added", std::to_string(result.vertices_added));
    p.is_fixed.resize(p.mesh.map.size(), false);   // the vertices a refinement added are free
    // UNREPAIRABLE_DEFECTS_LEFT: all that free vertices can repair is repaired
    send("status_success", result.status == MU::Untangling_status::SUCCESS ||
                           result.status == MU::Untangling_status::UNREPAIRABLE_DEFECTS_LEFT ? "1" : "0");
    send("hash", positions_hash(p.mesh));

    const Verdict after = check_mesh_file(p.mesh, p.is_fixed);
    send("inverted_after", std::to_string(after.inverted));
    send("overwound", std::to_string(after.overwound_vertices + after.overwound_edges));
    send("check_success", after.no_repairable_defect && after.non_manifold == 0 ? "1" : "0");
    send("defects_left_by_fixed_vertices", std::to_string(after.input_defects + after.input_defect_stars));
    send("done", "1");
  } catch(const std::bad_alloc&) {
    send("error", "out of memory");
  } catch(const Invalid_problem& e) {
    send("error", std::string("invalid problem: ") + one_line(e.what()));
  } catch(const std::exception& e) {
    send("error", one_line(e.what()));
  } catch(...) {
    send("error", "unknown exception");
  }
}

// ---------------------------------------------------------------------------
// The parent: one row per case and solver.

struct Row
{
  std::string case_name;
  std::string solver;
  std::map<std::string, std::string> values;   // what the child sent
  bool success = false;
  std::string outcome;        // "yes", or why not
  double wall_seconds = 0;    // as seen by the parent, loading included
  double peak_mib = -1;       // -1: unknown
  double killed_after = -1;   // the time limit the run was killed for overrunning; -1: not killed
  std::shared_ptr<Row> refined;   // --refine: the run with refinement (none: the fixed connectivity solved it)

  std::string get(const std::string& key, const std::string& missing = "—") const
  {
    const auto it = values.find(key);
    return it == values.end() ? missing : it->second;
  }
  bool has(const std::string& key) const { return values.count(key) != 0; }
  double seconds() const { return std::stod(get("seconds", "0")); }
  /// What the untangling took at least: its seconds, or the time limit it
  /// overran when it was killed before it could report them.
  double seconds_at_least() const { return has("seconds") ? seconds() : std::max(killed_after, 0.); }
};

std::string format_fixed(double value, int decimals)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string format_plain(double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string format_seconds(double seconds) { return format_fixed(seconds, seconds < 1 ? 3 : 2); }

void parse_child_output(const std::string& text, Row& row)
{
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line)) {
    const std::size_t tab = line.find('\t');
    if(tab == std::string::npos) continue;
    row.values[line.substr(0, tab)] = line.substr(tab + 1);
  }
}

// The untangler checks its time limit between eps steps only: a run is
// killed this long after the limit.
constexpr double kill_margin_seconds = 30;

Row run_case(const Case_spec& c, const std::string& solver, double time_limit, int threads, bool refine)
{
  Row row;
  row.case_name = c.name;
  row.solver = solver;

  int fds[2];
  if(::pipe(fds) != 0) {
    row.outcome = std::string("not run: pipe: ") + std::strerror(errno);
    return row;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if(pid < 0) {
    row.outcome = std::string("not run: fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return row;
  }
  if(pid == 0) {
    ::close(fds[0]);
    child_run(fds[1], c, solver, time_limit, threads, refine);
    ::close(fds[1]);
    ::_exit(0);   // no destructor, no flush of the parent's buffers
  }
  ::close(fds[1]);

  const double hard_limit = time_limit + kill_margin_seconds;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::string received;
  bool killed = false, pipe_open = true, exited = false;
  int status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof usage);
  while(!exited) {
    const double left = hard_limit - elapsed();
    if(left <= 0 && !killed) {
      ::kill(pid, SIGKILL);
      killed = true;
    }
    if(killed) {   // reap it, whatever is left in the pipe
      while(::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
      exited = true;
      break;
    }
    const int timeout_ms = static_cast<int>(std::min(left * 1000 + 1, 1000.));
    if(pipe_open) {
      struct pollfd p = {fds[0], POLLIN, 0};
      const int ready = ::poll(&p, 1, timeout_ms);
      if(ready > 0) {
        char buffer[4096];
        const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
        if(got > 0) received.append(buffer, static_cast<std::size_t>(got));
        else if(got == 0 || errno != EINTR) pipe_open = false;
      }
    } else {
      const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
      if(done == pid) exited = true;
      else ::usleep(10000);
    }
  }
  ::close(fds[0]);
  row.wall_seconds = elapsed();
  row.peak_mib = usage.ru_maxrss / 1024.;   // KiB on Linux; the child's alone (wait4), killed or not
  parse_child_output(received, row);

  if(killed) {
    row.outcome = "killed: still running after " + format_plain(hard_limit) + " s";
    row.killed_after = time_limit;
  } else if(WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    row.outcome = "crashed: signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    if(signal == SIGKILL) row.outcome += ", out of memory?";
  } else if(row.has("error")) {
    row.outcome = "error: " + row.get("error");
  } else if(!row.has("done")) {
    row.outcome = "no result: child exited with code " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  } else {
    const bool status_ok = row.get("status_success") == "1", check_ok = row.get("check_success") == "1";
    row.success = status_ok && check_ok;
    if(row.success) row.outcome = row.get("defects_left_by_fixed_vertices") == "0" ? "yes" : "yes, input defects aside";
    else if(status_ok) row.outcome = "no: status success, but the check finds it not locally invertible";
    else if(check_ok) row.outcome = "no: locally invertible, but status " + row.get("status");
    else row.outcome = "no: " + row.get("status");
  }
  return row;
}

// ---------------------------------------------------------------------------
// Output

std::string escape_cell(std::string text)
{
  std::string out;
  for(char ch : text) {
    if(ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

std::size_t display_width(const std::string& text)
{
  std::size_t width = 0;
  for(unsigned char ch : text) width += (ch & 0xC0) != 0x80;   // UTF-8 code points
  return width;
}

std::string table(const std::vector<Row>& rows)
{
  const std::vector<std::string> header = {"case", "#vertices", "#elements", "#fixed", "solver",
                                           "inverted before", "inverted after", "input defects", "success",
                                           "seconds", "eps steps", "solver iterations", "energy evaluations",
                                           "final energy", "final eps", "peak memory (MiB)", "result hash"};
  const bool refine = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.refined != nullptr; });
  std::vector<std::vector<std::string>> cells;
  for(const Row& r : rows) {
    const std::string ran = r.get("solver", r.solver);
    cells.push_back({r.case_name, r.get("vertices"), r.get("elements"), r.get("fixed"),
                     ran == r.solver ? r.solver : r.solver + ": " + ran,
                     r.get("inverted_before"), r.get("inverted_after"), r.get("input_defects"), r.outcome,
                     r.has("seconds") ? format_seconds(r.seconds()) : "—", r.get("eps_steps"),
                     r.get("iterations"), r.get("evaluations"), r.get("energy"), r.get("final_eps"), r.peak_mib >= 0 ? format_fixed(r.peak_mib, 1) : "—", r.get("hash")});
    if(refine) {
      const Row& f = r.refined ? *r.refined : r;   // solved without refinement: the same run
      cells.back().insert(cells.back().begin() + 10, {f.outcome, f.has("seconds") ? format_seconds(f.seconds()) : "—",
                                                      f.get("vertices_added")});
    }
    for(std::string& cell : cells.back()) cell = escape_cell(cell);
  }
  std::vector<std::string> columns = header;
  if(refine) columns.insert(columns.begin() + 10, {"--refine: success", "--refine: seconds", "vertices added"});
  std::vector<std::size_t> width(columns.size());
  for(std::size_t k = 0; k < columns.size(); ++k) {
    width[k] = display_width(columns[k]);
    for(const auto& line : cells) width[k] = std::max(width[k], display_width(line[k]));
  }
  // numbers right-aligned, text left-aligned
  auto numeric = [&](std::size_t k) {
    const std::size_t hash = refine ? 19 : 16;
    return k != 0 && k != 4 && k != 8 && k != hash && !(refine && k == 10);
  };
  std::ostringstream out;
  auto print_line = [&](const std::vector<std::string>& line) {
    out << "|";
    for(std::size_t k = 0; k < line.size(); ++k) {
      const std::string pad(width[k] - display_width(line[k]), ' ');
      out << " " << (numeric(k) ? pad + line[k] : line[k] + pad) << " |";
    }
    out << "\n";
  };
  print_line(columns);
  out << "|";
  for(std::size_t k = 0; k < columns.size(); ++k)
    out << (numeric(k) ? std::string(width[k] + 1, '-') + ":" : ":" + std::string(width[k] + 1, '-')) << "|";
  out << "\n";
  for(const auto& line : cells) print_line(line);
  return out.str();
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

std::string join(const std::vector<std::string>& names)
{
  if(names.empty()) return "none";
  std::string out;
  for(const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::string summary(const std::vector<Row>& rows, const std::vector<Case_spec>& cases,
                    const std::vector<std::string>& solvers)
{
  // rows are ordered case by case, solver by solver
  auto row_of = [&](std::size_t c, std::size_t s) -> const Row& { return rows[c * solvers.size() + s]; };
  std::ostringstream out;
  for(std::size_t a = 0; a < solvers.size(); ++a)
    for(std::size_t b = a + 1; b < solvers.size(); ++b) {
      std::size_t solved_a = 0, solved_b = 0;
      std::vector<double> ratios, bounds;   // bounds: every case either solved, at a lower bound of its ratio
      std::vector<std::string> only_a, only_b;
      for(std::size_t c = 0; c < cases.size(); ++c) {
        const Row& ra = row_of(c, a);
        const Row& rb = row_of(c, b);
        solved_a += ra.success;
        solved_b += rb.success;
        const double ratio = std::max(rb.seconds_at_least(), 1e-6) / std::max(ra.seconds_at_least(), 1e-6);
        if(ra.success && rb.success) ratios.push_back(ratio);
        else if(ra.success) only_a.push_back(cases[c].name);
        else if(rb.success) only_b.push_back(cases[c].name);
        // a lower bound of the ratio: b had not finished when it stopped; 0 where only b solved
        if(ra.success || rb.success) bounds.push_back(ra.success ? ratio : 0.);
      }
      out << "\n**" << solvers[a] << " vs " << solvers[b] << "** (" << cases.size() << " cases): "
          << solvers[a] << " solved " << solved_a << ", " << solvers[b] << " solved " << solved_b << ".\n\n";
      if(ratios.empty())
        out << "- median time ratio " << solvers[b] << "/" << solvers[a] << ": no case solved by both\n";
      else
        out << "- median time ratio " << solvers[b] << "/" << solvers[a] << ": " << format_fixed(median(ratios), 2)
            << " over the " << ratios.size() << " case(s) both solved (min " << format_fixed(*std::min_element(ratios.begin(), ratios.end()), 2)
            << ", max " << format_fixed(*std::max_element(ratios.begin(), ratios.end()), 2) << ")\n";
      if(bounds.size() > ratios.size())
        out << "- median time ratio " << solvers[b] << "/" << solvers[a] << " over the " << bounds.size()
            << " case(s) either solved, at a lower bound (solved only by " << solvers[a] << ": the time "
            << solvers[b] << " took before it stopped, or the time limit if it was killed; solved only by "
            << solvers[b] << ": 0): "
            << format_fixed(median(bounds), 2) << "\n";
      out << "- solved only by " << solvers[a] << ": " << escape_cell(join(only_a)) << "\n";
      out << "- solved only by " << solvers[b] << ": " << escape_cell(join(only_b)) << "\n";
    }
  if(solvers.size() == 1) {
    std::size_t solved = 0;
    for(const Row& r : rows) solved += r.success;
    out << "\n" << solvers[0] << " solved " << solved << " of " << cases.size() << " cases.\n";
  }
  for(std::size_t s = 0; s < solvers.size(); ++s) {
    std::size_t solved = 0, refined = 0;
    std::vector<double> added;
    for(std::size_t c = 0; c < cases.size(); ++c) {
      const Row& r = row_of(c, s);
      if(!r.refined) { solved += r.success; continue; }
      solved += r.refined->success;
      if(r.refined->success) {
        ++refined;
        const double vertices = std::stod(r.refined->get("vertices_added", "0"));
        if(vertices > 0) added.push_back(vertices);
      }
    }
    if(std::none_of(rows.begin(), rows.end(), [](const Row& r) { return r.refined != nullptr; })) break;
    out << "\n" << solvers[s] << " with --refine solved " << solved << " of " << cases.size() << " cases, "
        << refined << " of them in the run with refinement, " << added.size() << " with new vertices";
    if(!added.empty())
      out << " (vertices added: median " << format_plain(median(added)) << ", max "
          << format_plain(*std::max_element(added.begin(), added.end())) << ")";
    out << ".\n";
  }
  return out.str();
}

// ---------------------------------------------------------------------------

struct Arguments
{
  std::vector<std::string> solvers = {"auto", "lbfgs"};
  double time_limit = 120;
  int threads = 0;   // 0: TBB's default
  std::string markdown;
  bool refine = false;
  std::vector<Case_spec> cases;
};

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  std::vector<std::string> case_arguments;
  bool options_done = false;
  for(int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if(options_done || argument.empty() || argument[0] != '-') {
      case_arguments.push_back(argument);
      continue;
    }
    if(argument == "--") { options_done = true; continue; }
    if(argument == "--refine") { a.refine = true; continue; }
    if(argument == "-h" || argument == "--help") {
      std::cout << usage_text;
      std::exit(0);
    }
    std::string name = argument, value;
    const std::size_t equal = argument.find('=');
    if(equal != std::string::npos) {
      name = argument.substr(0, equal);
      value = argument.substr(equal + 1);
    }
    if(name != "--solver" && name != "--time-limit" && name != "--threads" && name != "--markdown")
      throw Usage_error{"unknown option '" + name + "'"};
    if(equal == std::string::npos) {
      if(i + 1 >= argc) throw Usage_error{name + " needs a value"};
      value = argv[++i];
    }
    if(name == "--solver") {
      a.solvers = split(value, ',');
      for(std::size_t k = 0; k < a.solvers.size(); ++k) {
        if(a.solvers[k] != "auto" && a.solvers[k] != "newton" && a.solvers[k] != "lbfgs")
          throw Usage_error{"unknown solver '" + a.solvers[k] + "' (auto, newton, lbfgs)"};
        if(std::find(a.solvers.begin(), a.solvers.begin() + k, a.solvers[k]) != a.solvers.begin() + k)
          throw Usage_error{"solver '" + a.solvers[k] + "' is listed twice"};
      }
    } else if(name == "--time-limit") {
      if(!parse_number(value, a.time_limit) || !(a.time_limit > 0))
        throw Usage_error{"--time-limit: '" + value + "' is not a positive number of seconds"};
    } else if(name == "--threads") {
      double threads = 0;
      if(!parse_number(value, threads) || !(threads >= 1) || threads != std::floor(threads) || threads > max_thread_count)
        throw Usage_error{"--threads: '" + value + "' is not a number of threads"};
      a.threads = static_cast<int>(threads);
    } else {
      if(value.empty()) throw Usage_error{"--markdown needs a file name"};
      a.markdown = value;
    }
  }
  if(case_arguments.empty()) throw Usage_error{"no case given"};
  for(const std::string& argument : case_arguments)
    try {
      for(Case_spec& c : parse_case(argument)) a.cases.push_back(std::move(c));
    } catch(const Case_error& e) {
      throw Usage_error{e.what()};
    }
  return a;
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  Arguments arguments;
  std::ofstream markdown;
  try {
    arguments = parse_arguments(argc, argv);
    if(!arguments.markdown.empty()) {
      markdown.open(arguments.markdown);   // opened now, so that a bad path fails before hours of runs
      if(!markdown) throw Usage_error{"--markdown: cannot write '" + arguments.markdown + "'"};
    }
  } catch(const Usage_error& e) {
    std::cerr << "benchmark_untangle: " << e.message << "\n\n" << usage_text;
    return 2;
  }

  std::vector<Row> rows;
  const std::size_t total = arguments.cases.size() * arguments.solvers.size();
  std::size_t index = 0;
  for(const Case_spec& c : arguments.cases)
    for(const std::string& solver : arguments.solvers) {
      const std::string label = "[" + std::to_string(++index) + "/" + std::to_string(total) + "] " + c.name + " " + solver;
      std::cerr << label << ": started" << std::endl;
      rows.push_back(run_case(c, solver, arguments.time_limit, arguments.threads, false));
      Row& r = rows.back();
      std::cerr << label << ": " << (r.success ? "success" : r.outcome) << ", "
                << (r.has("seconds") ? format_seconds(r.seconds()) + " s untangling, " : std::string())
                << format_seconds(r.wall_seconds) << " s in all, "
                << (r.peak_mib >= 0 ? format_fixed(r.peak_mib, 1) : std::string("?")) << " MiB" << std::endl;
      if(arguments.refine && !r.success) {
        r.refined = std::make_shared<Row>(run_case(c, solver, arguments.time_limit, arguments.threads, true));
        std::cerr << label << " --refine: " << (r.refined->success ? "success" : r.refined->outcome) << ", "
                  << r.refined->get("vertices_added", "?") << " vertices added, "
                  << (r.refined->has("seconds") ? format_seconds(r.refined->seconds()) + " s" : std::string("?"))
                  << std::endl;
      }
    }

  std::ostringstream report;
  report << (arguments.threads > 0 ? "At most " + std::to_string(arguments.threads) + " thread(s). " : std::string())
         << "Time limit " << format_plain(arguments.time_limit) << " s per run (killed at "
         << format_plain(arguments.time_limit + kill_margin_seconds) << " s). inverted before/after: elements inverted "
         << "relative to their rest element (exact predicates); success: the result is locally invertible "
         << "(check) and the untangler reports success; seconds: the untangling call alone; result hash: "
         << "FNV-1a of the resulting coordinates' bytes."
         << (arguments.refine ? " --refine: the run with local refinement, where the fixed connectivity did not "
                                "succeed (its own process and time limit; otherwise the same run, 0 vertices added)."
                              : "")
         << "\n\n"
         << table(rows) << summary(rows, arguments.cases, arguments.solvers);
  std::cout << report.str() << std::flush;
  if(markdown.is_open()) {
    markdown << report.str();
    markdown.close();
    if(!markdown) std::cerr << "benchmark_untangle: could not write " << arguments.markdown << std::endl;
  }
  return 0;
}
