#include "reports/cli/shards.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/kernel/shard.hpp"
#include "reports/cli/cli.hpp"
#include "reports/cli/commands.hpp"
#include "reports/data/inputs.hpp"
#include "reports/data/output.hpp"
#include "reports/data/schemas.hpp"

namespace steplab {
namespace {

using Json = nlohmann::ordered_json;
constexpr std::string_view kSchema = schema::part;

// The bytes of a hex string, or nullopt if it is not one.
std::optional<std::string> unhex(const std::string& text) {
  if (text.size() % 2) return std::nullopt;
  const auto nibble = [](char c) { return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1; };
  std::string out;
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int hi = nibble(text[i]), lo = nibble(text[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out += static_cast<char>(hi * 16 + lo);
  }
  return out;
}

std::string command_text(const Json& command) {
  std::string out = "steplab";
  for (const auto& a : command) out += " " + a.get<std::string>();
  return out;
}

struct Call {
  std::size_t tasks;
  std::vector<std::pair<std::size_t, std::string>> results;  // task, its result's bytes
};

struct Part {
  std::string path;
  Json doc;
  int index = 0, count = 0;
  std::vector<Call> calls;  // decoded from doc["calls"]
};

// A part read and its form checked; a UsageError naming the file otherwise.
Part read_part(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError(fmt::format("{}: cannot be read; accepted: part files written by --shard", path));
  Part p{path, Json::parse(in, nullptr, false), 0, 0, {}};
  const Json& d = p.doc;
  const auto bad = [&](std::string_view what) {
    return UsageError(fmt::format("{}: {}; accepted: a part written by steplab study ... --shard i/N (schema {})", path, what, kSchema));
  };
  if (d.is_discarded() || !d.is_object()) throw bad("not JSON");
  if (!d.contains("schema") || d["schema"] != kSchema) throw bad("not a steplab part");
  if (!d.contains("command") || !d["command"].is_array() || d["command"].empty()) throw bad("no command");
  for (const Json& a : d["command"])
    if (!a.is_string()) throw bad("a command argument that is not text");
  const Json& s = d.contains("shard") ? d["shard"] : Json();
  if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer()) throw bad("no shard [i, N]");
  p.index = s[0].get<int>(), p.count = s[1].get<int>();
  if (p.count < 1 || p.count > kMaxShards || p.index < 1 || p.index > p.count) throw bad("a shard outside 1..N");
  if (!d.contains("calls") || !d["calls"].is_array()) throw bad("no calls");
  for (const Json& c : d["calls"]) {
    if (!c.is_object() || !c.contains("tasks") || !c["tasks"].is_number_unsigned() || !c.contains("results") ||
        !c["results"].is_object())
      throw bad("a call without tasks and results");
    Call& call = p.calls.emplace_back(Call{c["tasks"].get<std::size_t>(), {}});
    for (const auto& [task, text] : c["results"].items()) {
      const bool number = !task.empty() && task.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t i = number ? std::stoull(task) : call.tasks;
      std::optional<std::string> bytes = text.is_string() ? unhex(text.get<std::string>()) : std::nullopt;
      if (i >= call.tasks || !bytes)
        throw bad(fmt::format("a result of task '{}' that is not hex bytes of a task of its call", task));
      call.results.emplace_back(i, std::move(*bytes));
    }
  }
  p.doc.erase("calls");  // held decoded in p.calls
  return p;
}

}  // namespace

void add_merge_command(CLI::App& app, MergeArgs& a) {
  CLI::App* cmd = app.add_subcommand("merge", "put the parts of a study run with --shard i/N together: the JSON one "
                                              "process would have written");
  cmd->add_option("parts", a.parts, "the N part files, in any order")->type_name("FILE");
  cmd->add_option("--json", a.json, "write the study's JSON to this file");
}

int merge_command(MergeArgs& a, Context& ctx) {
  if (a.parts.empty()) throw UsageError("merge has no parts; accepted: steplab merge PART.json... --json OUT");
  if (a.json.empty()) throw UsageError("merge has no --json; accepted: steplab merge PART.json... --json OUT");
  if (ctx.dry_run) return 0;
  std::vector<Part> parts;
  for (const std::string& path : a.parts) parts.push_back(read_part(path));
  const Part& first = parts.front();
  std::map<int, const Part*> by_index;
  for (const Part& p : parts) {
    if (p.doc["command"] != first.doc["command"])
      throw UsageError(fmt::format("{} is from `{}`, {} from `{}`; accepted: the parts of one command line", p.path,
                                   command_text(p.doc["command"]), first.path, command_text(first.doc["command"])));
    if (p.count != first.count)
      throw UsageError(fmt::format("{} is shard {}/{}, {} one of {}; accepted: parts of one split", p.path, p.index, p.count,
                                   first.path, first.count));
    const auto [it, fresh] = by_index.emplace(p.index, &p);
    if (!fresh)
      throw UsageError(fmt::format("{} and {} are both shard {}/{}; accepted: each shard once", it->second->path, p.path,
                                   p.index, p.count));
    bool same = p.calls.size() == first.calls.size();
    for (std::size_t k = 0; same && k < p.calls.size(); ++k) same = p.calls[k].tasks == first.calls[k].tasks;
    if (!same)
      throw UsageError(fmt::format("{} holds other work than {} (other task lists); accepted: the parts of one command line",
                                   p.path, first.path));
  }
  for (int i = 1; i <= first.count; ++i)
    if (!by_index.count(i))
      throw UsageError(fmt::format("shard {}/{} is missing; accepted: all {} parts", i, first.count, first.count));

  WorkLog log{WorkMode::Replay, 1, first.count, {}, 0};
  for (const Call& call : first.calls) log.calls.emplace_back(call.tasks);
  for (Part& p : parts)
    for (std::size_t k = 0; k < log.calls.size(); ++k)
      for (auto& [task, bytes] : p.calls[k].results) {
        auto& slot = log.calls[k][task];
        if (slot) throw UsageError(fmt::format("{}: task {} of call {} is in two parts; accepted: parts of one split", p.path, task, k + 1));
        slot = std::move(bytes);
      }
  Context replay;
  replay.progress = ctx.progress;
  replay.log = std::move(log);

  std::vector<std::string> args;
  for (const Json& x : first.doc["command"]) args.push_back(x.get<std::string>());
  args.insert(args.end(), {"--json", a.json});
  try {
    return dispatch(args, replay);
  } catch (const PartMismatch& e) {
    throw UsageError(fmt::format("{} ... do not fit `{}`: {}; accepted: the parts of one command line of this steplab",
                                 first.path, command_text(first.doc["command"]), e.what()));
  }
}

}  // namespace steplab
