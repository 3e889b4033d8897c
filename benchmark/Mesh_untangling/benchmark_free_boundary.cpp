// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The free-boundary stress benchmark (issue 22): seeded families of 2D and
// 3D problems with free boundaries, each instance generated and untangled
// through the public entry points in a forked child (peak memory per
// instance; a crash or a hang stops only that instance), then judged by the
// exact checks.  Prints one markdown row per family.
//
//   benchmark_free_boundary [--family NAME,...] [--quick|--large] [--time-limit S] [--threads N]
//                           [--instance NAME,...] [--verbose] [--trace] [--write DIR] [--list]

#include "free_boundary_families.h"
#include "memory_reuse.h"
#include "thread_limit.h"

#include <CGAL/Mesh_untangling/IO/mesh_file_io.h>
#include <CGAL/Mesh_untangling/Untangling_step.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace Mesh_untangling_tools;

namespace {

const char* const usage_text =
  "usage: benchmark_free_boundary [--family NAME,...] [--quick|--large] [--time-limit SECONDS] [--threads N]\n"
  "                               [--instance NAME,...] [--data DIR] [--verbose] [--trace] [--write DIR] [--list]\n"
  "\n"
  "Generates the seeded instances of the free-boundary stress families, untangles each through\n"
  "CGAL::untangle_mesh (triangles) or CGAL::untangle_simplex_soup (tetrahedra) with the default\n"
  "options in a forked child, and judges the result exactly: no inverted element, no over-wound\n"
  "star or edge fan, the fixed vertices bitwise in place, and where a valid map with a simple\n"
  "boundary is known, no boundary crossing.  Prints one markdown row per family.\n"
  "\n"
  "  --family NAME,...     families to run (default: all; --list shows them)\n"
  "  --quick               a few small instances per family\n"
  "  --large               more instances, and the 200k-tet bars and locked regions\n"
  "  --time-limit SECONDS  the untangler's time limit per instance (default 60); a child still\n"
  "                        running 15 s past it is killed\n"
  "  --threads N           at most N threads in the untangler (default: TBB's choice)\n"
  "  --instance NAME,...   only these instances (names as --verbose or --list prints them)\n"
  "  --data DIR            the folder of other groups' meshes that the family real-meshes reads\n"
  "                        (default: the build's MESH_UNTANGLING_DATA_DIR, ../shared/data); without\n"
  "                        them that family has no instance\n"
  "  --verbose             one line per instance with its failure figures\n"
  "  --trace               one line per eps step on stderr (motion of the continuation, stage, eps,\n"
  "                        min det J, non-positive elements, seconds)\n"
  "  --write DIR           write each selected instance as DIR/NAME.input (rest, map, fixed\n"
  "                        vertices: the command-line tool reads it) instead of running it\n"
  "  --list                list the families and their instances, run nothing\n";

struct Usage_error
{
  std::string message;
};

struct Arguments
{
  std::vector<std::string> families;
  Family_size size = Family_size::DEFAULT;
  double time_limit = 60;
  int threads = 0;
  std::vector<std::string> instances;
  bool verbose = false, list = false, trace = false;
  std::string write_directory;
  std::string data_directory = MESH_UNTANGLING_DATA_DIR;
};

std::vector<std::string> split_list(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while(std::getline(in, part, ','))
    if(!part.empty()) parts.push_back(part);
  return parts;
}

bool parse_positive(const std::string& text, double& value)
{
  if(text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if(errno != 0 || *end != '\0' || !std::isfinite(v) || !(v > 0)) return false;
  value = v;
  return true;
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  std::vector<std::string> known;
  for(const auto& f : free_boundary_families()) known.push_back(f.name);
  bool quick = false, large = false;
  for(int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error{argument + " needs a value"};
      return argv[++i];
    };
    if(argument == "-h" || argument == "--help") {
      std::cout << usage_text;
      std::exit(0);
    } else if(argument == "--quick") quick = true;
    else if(argument == "--large") large = true;
    else if(argument == "--verbose") a.verbose = true;
    else if(argument == "--trace") a.trace = true;
    else if(argument == "--list") a.list = true;
    else if(argument == "--family") {
      const std::string v = value();
      a.families = split_list(v);
      if(a.families.empty()) throw Usage_error{"--family needs at least one family name"};
      for(const std::string& f : a.families)
        if(std::find(known.begin(), known.end(), f) == known.end())
          throw Usage_error{"--family: unknown family '" + f + "' (--list shows them)"};
    } else if(argument == "--instance") {
      a.instances = split_list(value());
      if(a.instances.empty()) throw Usage_error{"--instance needs at least one instance name"};
    } else if(argument == "--time-limit") {
      const std::string v = value();
      if(!parse_positive(v, a.time_limit)) throw Usage_error{"--time-limit: '" + v + "' is not a positive number of seconds"};
    } else if(argument == "--threads") {
      const std::string v = value();
      double threads = 0;
      if(!parse_positive(v, threads) || threads != std::floor(threads) || threads > max_thread_count)
        throw Usage_error{"--threads: '" + v + "' is not a positive number of threads"};
      a.threads = int(threads);
    } else if(argument == "--data") {
      a.data_directory = value();
      if(a.data_directory.empty()) throw Usage_error{"--data needs a folder"};
    } else if(argument == "--write") {
      a.write_directory = value();
      if(a.write_directory.empty()) throw Usage_error{"--write needs a folder"};
    } else
      throw Usage_error{"unknown argument '" + argument + "'"};
  }
  if(quick && large) throw Usage_error{"--quick and --large exclude each other"};
  a.size = quick ? Family_size::QUICK : large ? Family_size::LARGE : Family_size::DEFAULT;
  if(a.families.empty()) a.families = known;
  return a;
}

// ---------------------------------------------------------------------------
// The child: generates, untangles and judges one instance, sends "key\tvalue" lines.

void write_all(int fd, const std::string& text)
{
  const char* data = text.data();
  std::size_t left = text.size();
  while(left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if(written < 0) {
      if(errno == EINTR) continue;
      return;
    }
    data += written;
    left -= std::size_t(written);
  }
}

void child_run(int fd, const Family_instance& instance, double time_limit, int threads, bool trace)
{
  const Thread_limit limit(threads);
  auto send = [fd](const std::string& key, const std::string& value) { write_all(fd, key + "\t" + value + "\n"); };
  try {
    Mesh_file mesh = instance.make();
    std::function<bool(const CGAL::Mesh_untangling::Untangling_step&)> tracer;
    if(trace)
      tracer = [](const CGAL::Mesh_untangling::Untangling_step& s) {
        std::fprintf(stderr, "  step %4zu motion %.4f stage %d eps %.3e min det %.3e non-positive %zu (%zu iterations) %.2f s\n",
                     s.step, s.motion, s.stage, s.epsilon, s.min_det, s.non_positive, s.inner_iterations, s.seconds);
        return true;
      };
    const Judgement j = untangle_and_judge(mesh, time_limit, tracer);
    std::ostringstream out;
    out.precision(4);
    out << j.vertices << " " << j.elements << " " << j.fixed << " " << j.seconds << " " << j.inverted_before << " "
        << j.inverted << " " << j.overwound_interior_vertices << " " << j.overwound_boundary_vertices << " "
        << j.overwound_edges << " " << j.fixed_moved << " " << j.boundary_crossings << " " << j.phantoms << " "
        << j.continuation_steps << " " << j.continuation_motion << " " << j.eps_steps << " " << j.final_epsilon << " "
        << j.input_returned << " "
        << j.locally_invertible << " " << j.boundary_simple << " " << j.size;
    send("figures", out.str());
    send("status", j.status);
  } catch(const std::bad_alloc&) {
    send("error", "out of memory");
  } catch(const std::exception& e) {
    send("error", e.what());
  }
}

// ---------------------------------------------------------------------------
// The parent

struct Outcome
{
  std::string name;
  bool ran = false;   // the child reported its figures
  Judgement j;
  std::string status, failure;   // failure: why there are no figures
  double wall_seconds = 0, peak_mib = 0;
  bool passes = false;
};

constexpr double kill_margin_seconds = 15;

Outcome run_in_child(const Family_instance& instance, double time_limit, int threads, bool trace)
{
  Outcome o;
  o.name = instance.name;
  int fds[2];
  if(::pipe(fds) != 0) {
    o.failure = std::string("pipe: ") + std::strerror(errno);
    return o;
  }
  std::cout.flush();
  std::cerr.flush();
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if(pid < 0) {
    o.failure = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return o;
  }
  if(pid == 0) {
    ::close(fds[0]);
    child_run(fds[1], instance, time_limit, threads, trace);
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::string received;
  bool killed = false, pipe_open = true;
  int status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof usage);
  for(;;) {
    const double left = time_limit + kill_margin_seconds - elapsed();
    if(left <= 0) {
      ::kill(pid, SIGKILL);
      killed = true;
      while(::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
      break;
    }
    if(pipe_open) {
      struct pollfd p = {fds[0], POLLIN, 0};
      if(::poll(&p, 1, int(std::min(left * 1000 + 1, 1000.))) > 0) {
        char buffer[4096];
        const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
        if(got > 0) received.append(buffer, std::size_t(got));
        else if(got == 0 || errno != EINTR) pipe_open = false;
      }
    } else if(::wait4(pid, &status, WNOHANG, &usage) == pid) {
      break;
    } else {
      ::usleep(10000);
    }
  }
  ::close(fds[0]);
  o.wall_seconds = elapsed();
  o.peak_mib = double(usage.ru_maxrss) / 1024.;

  std::map<std::string, std::string> values;
  std::istringstream lines(received);
  for(std::string line; std::getline(lines, line);) {
    const std::size_t tab = line.find('\t');
    if(tab != std::string::npos) values[line.substr(0, tab)] = line.substr(tab + 1);
  }
  if(killed) o.failure = "killed after " + std::to_string(int(time_limit + kill_margin_seconds)) + " s";
  else if(WIFSIGNALED(status)) o.failure = std::string("crashed: ") + strsignal(WTERMSIG(status));
  else if(values.count("error")) o.failure = "error: " + values["error"];
  else if(!values.count("figures")) o.failure = "no result";
  else {
    std::istringstream in(values["figures"]);
    Judgement& j = o.j;
    in >> j.vertices >> j.elements >> j.fixed >> j.seconds >> j.inverted_before >> j.inverted >>
        j.overwound_interior_vertices >> j.overwound_boundary_vertices >> j.overwound_edges >> j.fixed_moved >>
        j.boundary_crossings >> j.phantoms >> j.continuation_steps >> j.continuation_motion >> j.eps_steps >>
        j.final_epsilon >>
        j.input_returned >> j.locally_invertible >> j.boundary_simple >> j.size;
    j.overwound_vertices = j.overwound_interior_vertices + j.overwound_boundary_vertices;
    o.ran = bool(in);
    o.status = values["status"];
    if(!o.ran) o.failure = "unreadable figures";
  }
  o.passes = o.ran && o.j.passes(instance.boundary_should_be_simple);
  return o;
}

std::string fixed_decimals(double value, int decimals)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string instance_line(const Outcome& o, const Family_instance& instance)
{
  std::ostringstream out;
  out << (o.passes ? "  ok   " : "  FAIL ") << o.name << ": ";
  if(!o.ran) {
    out << o.failure << ", " << fixed_decimals(o.wall_seconds, 1) << " s, " << fixed_decimals(o.peak_mib, 0) << " MiB";
    return out.str();
  }
  const Judgement& j = o.j;
  out << j.elements << " elements, " << j.fixed << " fixed; " << j.inverted_before << " inverted before -> "
      << j.inverted << " inverted, over-wound vertices " << j.overwound_interior_vertices << " interior + "
      << j.overwound_boundary_vertices << " boundary, over-wound edges " << j.overwound_edges << ", fixed moved "
      << j.fixed_moved << ", size " << j.size << " of the rest's, boundary crossings " << j.boundary_crossings
      << (instance.boundary_should_be_simple ? " (should be 0)" : " (not judged)") << "; " << j.phantoms
      << " phantoms, " << j.continuation_steps << " continuation steps"
      << (j.continuation_motion > 0 && j.continuation_motion < 1
            ? " (to motion " + fixed_decimals(j.continuation_motion, 4) + ")" : std::string())
      << ", " << j.eps_steps << " eps steps, final eps "
      << j.final_epsilon << (j.input_returned ? ", input returned" : "") << "; " << fixed_decimals(j.seconds, 2)
      << " s, " << fixed_decimals(o.peak_mib, 0) << " MiB; " << o.status;
  return out.str();
}

double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

void write_instances(const std::vector<Family_instance>& instances, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  for(const Family_instance& instance : instances) {
    const std::string path = (std::filesystem::path(directory) / (instance.name + ".input")).string();
    CGAL::Mesh_untangling::IO::write_mesh_file(path, instance.make());
    std::cout << path << "\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  Mesh_untangling_tools::reuse_freed_memory();
  Arguments a;
  std::vector<std::pair<std::string, std::vector<Family_instance>>> families;
  try {
    a = parse_arguments(argc, argv);
    std::size_t selected = 0;
    for(const std::string& f : a.families) {
      std::vector<Family_instance> instances = free_boundary_family(f, a.size, a.data_directory);
      if(instances.empty() && a.instances.empty())
        std::cerr << "benchmark_free_boundary: " << f << ": no instance (its meshes are not under '" << a.data_directory
                  << "'): skipped\n";
      if(!a.instances.empty())
        instances.erase(std::remove_if(instances.begin(), instances.end(), [&](const Family_instance& i) {
          return std::find(a.instances.begin(), a.instances.end(), i.name) == a.instances.end();
        }), instances.end());
      selected += instances.size();
      if(!instances.empty()) families.emplace_back(f, std::move(instances));
    }
    if(selected == 0)
      throw Usage_error{a.instances.empty() ? "no instance to run: the selected families have none here"
                                            : "--instance: no instance of the selected families has that name (--list shows them)"};
  } catch(const Usage_error& e) {
    std::cerr << "benchmark_free_boundary: " << e.message << "\n\n" << usage_text;
    return 2;
  }

  if(a.list) {
    for(const auto& f : free_boundary_families()) {
      const auto it = std::find_if(families.begin(), families.end(), [&](const auto& p) { return p.first == f.name; });
      if(it == families.end()) continue;
      std::cout << f.name << ": " << f.description << "\n";
      for(const Family_instance& i : it->second) std::cout << "  " << i.name << "\n";
    }
    return 0;
  }
  if(!a.write_directory.empty()) {
    try {
      for(const auto& f : families) write_instances(f.second, a.write_directory);
    } catch(const std::exception& e) {
      std::cerr << "benchmark_free_boundary: --write: " << e.what() << "\n";
      return 1;
    }
    return 0;
  }

  std::ostringstream table;
  table << "| family | instances | locally invertible | all checks | median s | max s | peak MiB | MiB per 1k elements (largest) |\n"
        << "|:--|--:|--:|--:|--:|--:|--:|--:|\n";
  std::size_t total = 0, total_invertible = 0, total_passed = 0;
  for(const auto& [family, instances] : families) {
    std::cout << family << ":" << std::endl;
    std::size_t invertible = 0, passed = 0;
    std::vector<double> seconds;
    double peak = 0, peak_per_element = 0;   // the latter: of the largest instance
    std::size_t largest = 0;
    for(const Family_instance& instance : instances) {
      const Outcome o = run_in_child(instance, a.time_limit, a.threads, a.trace);
      invertible += o.ran && o.j.locally_invertible && o.j.fixed_moved == 0;
      passed += o.passes;
      seconds.push_back(o.ran ? o.j.seconds : o.wall_seconds);
      peak = std::max(peak, o.peak_mib);
      if(o.ran && o.j.elements > largest) {
        largest = o.j.elements;
        peak_per_element = o.peak_mib / double(o.j.elements) * 1000;
      }
      if(a.verbose || !o.passes) std::cout << instance_line(o, instance) << std::endl;
    }
    total += instances.size();
    total_invertible += invertible;
    total_passed += passed;
    table << "| " << family << " | " << instances.size() << " | " << invertible << " | " << passed << " | "
          << fixed_decimals(median(seconds), 2) << " | " << fixed_decimals(*std::max_element(seconds.begin(), seconds.end()), 2)
          << " | " << fixed_decimals(peak, 0) << " | " << fixed_decimals(peak_per_element, 2) << " |\n";
  }
  table << "| all | " << total << " | " << total_invertible << " | " << total_passed << " | | | | |\n";
  std::cout << "\nTime limit " << a.time_limit << " s per instance"
            << (a.threads > 0 ? ", at most " + std::to_string(a.threads) + " thread(s)" : std::string())
            << ". locally invertible: no inverted element, no over-wound star or edge fan, fixed vertices in place "
               "(exact); all checks: also a simple boundary image where a valid map with one is known.\n\n"
            << table.str();
  return 0;
}
