// tripack: the command line. Every command comes from the command table (commands/table.cpp) and
// declares its own options; this file binds them with CLI11, parses, and dispatches.
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <thread>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/help.hpp"
#include "core/option_values.hpp"

namespace {

using namespace tripack;

// OptionList on a CLI11 subcommand: each option bound to its field, its default shown from the
// field's value.
class CliOptions : public OptionList {
  class CliHandle : public Handle {
    CLI::Option* option_;

   public:
    explicit CliHandle(CLI::Option* option) : option_(option) {}
    // CLI11's Range prints its bounds with std::to_string ("2.000000 to 100000.000000"): the
    // same check with the bounds as option_range writes them ("2 to 100000", "0.001 to ...").
    Handle& range(double min, double max) override {
      const std::string bounds = option_range(min, max);
      option_->check(CLI::Validator(
          [min, max, bounds](std::string& input) {
            double value = 0;
            if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
            if (!(value >= min && value <= max))
              return "Value " + input + " not in range " + bounds;
            return std::string();
          },
          ""));
      option_->type_name(option_->get_type_name() + " in [" + option_bound(min) + " - " +
                         option_bound(max) + "]");
      return *this;
    }
    Handle& required() override {
      option_->required();
      return *this;
    }
    Handle& shown_default(const std::string& text) override {
      option_->default_str(text);
      return *this;
    }
  };
  CLI::App* app_;
  std::vector<std::unique_ptr<CliHandle>> handles_;

  Handle& keep(CLI::Option* option) {
    handles_.push_back(std::make_unique<CliHandle>(option));
    return *handles_.back();
  }
  template <class T>
  Handle& bind(const std::string& names, T& field, const std::string& help) {
    return keep(app_->add_option(names, field, help)->capture_default_str());
  }

 public:
  explicit CliOptions(CLI::App* app) : app_(app) {}
  Handle& option(const std::string& n, std::string& f, const std::string& h) override {
    return keep(app_->add_option(n, f, h)->capture_default_str());
  }
  Handle& option(const std::string& n, int& f, const std::string& h) override {
    return bind(n, f, h);
  }
  Handle& option(const std::string& n, long& f, const std::string& h) override {
    return bind(n, f, h);
  }
  Handle& option(const std::string& n, long long& f, const std::string& h) override {
    return bind(n, f, h);
  }
  Handle& option(const std::string& n, double& f, const std::string& h) override {
    return bind(n, f, h);
  }
  Handle& option(const std::string& n, std::uint64_t& f, const std::string& h) override {
    return bind(n, f, h);
  }
  Handle& option(const std::string& n, std::vector<std::string>& f, const std::string& h) override {
    return keep(app_->add_option(n, f, h));
  }
  Handle& flag(const std::string& n, bool& f, const std::string& h) override {
    return keep(app_->add_flag(n, f, h));
  }
  Handle& flag_action(const std::string& n, std::function<void()> act,
                      const std::string& h) override {
    return keep(app_->add_flag_callback(n, std::move(act), h));
  }
  Handle& parsed(const std::string& n, std::function<void(const std::string&)> set,
                 const std::string& shown_default, const std::string& h) override {
    auto* o = app_->add_option_function<std::string>(n, std::move(set), h);
    if (!shown_default.empty()) o->default_str(shown_default);
    return keep(o);
  }
};

// One line on stderr; in JSON or CSV also the error on stdout in that format, so a program
// reading stdout always gets what it asked for (commands/help.hpp).
int fail(const std::string& message, const std::string& format, int code) {
  std::cerr << "tripack: error: " << message << "\n";
  std::cout << commands::error_output(message, format) << std::flush;
  return code;
}

// Ctrl-C and SIGTERM (mpirun passes a Ctrl-C on to the ranks as SIGTERM) are taken by a thread
// of their own (sigwait), not a handler. Blocked before any other thread starts, so every thread
// inherits the mask and only this one receives them. Signals within kSameSignal of the last one
// counted are that one again: GNU timeout and a terminal's Ctrl-C signal both the process and its
// group, so one request often arrives twice. The first stops the job after the items under way;
// the second abandons those items, and the job still reports and records what finished; only a
// third ends the program at once (docs/cli.md, "Ctrl-C").
constexpr std::chrono::milliseconds kSameSignal{1000};

void cancel_on_signals(CancelToken& cancel, const char* one_item_lost) {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread([signals, &cancel, one_item_lost] {
    // A person at a terminal sees the first request acknowledged at once (the progress line
    // ended first); a log gets only the job's one closing line ("tripack: cancelled: ...").
    const bool terminal = isatty(STDERR_FILENO);
    const char* fresh_line = terminal ? "\n" : "";
    int counted = 0;
    auto last = std::chrono::steady_clock::now();
    for (;;) {
      int received = 0;
      if (sigwait(&signals, &received) != 0) continue;
      const auto now = std::chrono::steady_clock::now();
      if (counted > 0 && now - last < kSameSignal) continue;
      last = now;
      ++counted;
      if (counted == 1) {
        cancel.cancel();
        if (terminal)
          std::cerr << "\ntripack: stopping after the items under way (again to stop at once)\n";
        // A one-item job inside a long library call (no check for minutes) ends here after the
        // grace time, with the closing line it would have written; nothing of it is kept anyway.
        if (one_item_lost)
          std::thread([&cancel, one_item_lost, fresh_line] {
            std::this_thread::sleep_for(commands::kOneItemGrace);
            if (!cancel.claim_ending()) return;
            std::cerr << fresh_line;
            std::_Exit(commands::cancelled(one_item_lost));
          }).detach();
      } else if (counted == 2) {
        cancel.abandon();
        std::cerr << fresh_line
                  << "tripack: stopping at once: the items under way are abandoned, what "
                     "finished is reported (again to exit without it)\n";
      } else {
        std::_Exit(commands::kCancelledExit);
      }
    }
  }).detach();
}

// A Markdown cell: pipes escaped, so that a help text cannot break the table.
std::string cell(std::string text) {
  for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2)
    text.replace(at, 1, "\\|");
  return text;
}

// docs/cli.md's option tables, from the options as bound (scripts/cli-doc.py splices them into
// the manual, and a test fails when the manual differs): one block per command.
void print_markdown_options(const std::string& command, const CLI::App& app) {
  std::cout << "<!-- options of " << command << ": generated by `tripack --markdown-options` -->\n"
            << "| option | value | default | meaning |\n|---|---|---|---|\n";
  for (const CLI::Option* o : app.get_options()) {
    std::string names = o->get_name(true, true);
    // "--no-polish{false}": CLI11's spelling of a negated flag's value, not part of its name.
    for (std::size_t open; (open = names.find('{')) != std::string::npos;)
      names.erase(open, names.find('}', open) - open + 1);
    if (names == "-h,--help" || names == "--help") continue;
    std::string value = o->get_type_name();
    if (const auto bracket = value.find(" in ["); bracket != std::string::npos)
      value = value.substr(0, bracket) + " " + value.substr(bracket + 4);
    std::string shown;
    for (std::size_t start = 0, comma;; start = comma + 1) {
      comma = names.find(',', start);
      shown += (shown.empty() ? "" : ", ") + std::string("`") +
               names.substr(start, comma == std::string::npos ? comma : comma - start) + "`";
      if (comma == std::string::npos) break;
    }
    const std::string fallback = o->get_required() ? "required" : "";
    const std::string given = o->get_default_str();
    std::cout << "| " << shown << " | " << cell(o->get_expected_min() == 0 ? "" : value) << " | "
              << cell(given.empty() ? fallback : "`" + given + "`") << " | "
              << cell(o->get_description()) << " |\n";
  }
  std::cout << "<!-- end of the options of " << command << " -->\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"tripack: dense packings of equal disks in an equilateral triangle"};
  cli.require_subcommand(1);
  cli.footer(commands::help_footer());
  commands::Context context;
  cli.add_option("--catalogue", context.catalogue,
                 "classes.yaml to use (default: $TRIPACK_CATALOGUE or the installed one)");
  struct Bound {
    const commands::CommandEntry* entry;
    CLI::App* app;
    std::unique_ptr<commands::Command> command;
  };
  std::vector<Bound> bound;
  std::map<std::string, CLI::App*> groups;
  std::vector<std::unique_ptr<CliOptions>> options;
  for (const auto& entry : commands::command_table()) {
    CLI::App* parent = &cli;
    std::string name = entry.name;
    if (const auto space = name.find(' '); space != std::string::npos) {
      const std::string group = name.substr(0, space);
      auto& g = groups[group];
      if (!g) {
        g = cli.add_subcommand(group, commands::group_summary(group));
        g->require_subcommand(1);
      }
      parent = g;
      name = name.substr(space + 1);
    }
    Bound b{&entry, parent->add_subcommand(name, entry.summary), entry.make()};
    options.push_back(std::make_unique<CliOptions>(b.app));
    b.command->declare(*options.back());
    bound.push_back(std::move(b));
  }
  if (argc == 2 && std::string(argv[1]) == "--markdown-options") {
    for (const auto& b : bound) print_markdown_options(b.entry->name, *b.app);
    return 0;
  }
  const std::string format = commands::requested_format(argc, argv);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(e.what(), format, 2);
  } catch (const std::exception& e) {  // an option's own parse (a range, a convention)
    return fail(e.what(), format, 2);
  }
  CancelToken cancel;  // outlives the signal thread: main never returns before exit
  try {
    for (auto& b : bound) {
      if (!*b.app) continue;
      if (b.entry->long_job) {
        cancel_on_signals(cancel, b.entry->one_item_lost);
        context.cancel = &cancel;
      }
      return b.command->run(context);
    }
  } catch (const std::exception& e) {
    return fail(e.what(), format, 1);
  }
  return 0;
}
