// The repository's own files, as the tests that tie docs/ to the code read them: the root (CIRCLES_SOURCE_DIR),
// a file's lines and text, the tracked files, the Markdown docs, and what a shell command prints.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace circles::testing {

inline const std::filesystem::path root = CIRCLES_SOURCE_DIR;

// What `command` (run by /bin/sh) writes on stdout, and its exit status.
struct Output {
  std::string text;
  int status = -1;
};
inline Output output_of(const std::string& command) {
  Output out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char chunk[4096];
  for (std::size_t got; (got = std::fread(chunk, 1, sizeof chunk, pipe)) > 0;) out.text.append(chunk, got);
  const int status = pclose(pipe);
  out.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

inline std::string quoted(const std::filesystem::path& path) { return std::string("'").append(path.string()).append("'"); }

inline std::vector<std::string> lines_of(const std::filesystem::path& relative) {
  std::ifstream in(root / relative);
  if (!in) throw std::runtime_error("cannot read " + (root / relative).string());
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string text_of(const std::filesystem::path& relative) {
  std::string all;
  for (const std::string& line : lines_of(relative)) all += line + '\n';
  return all;
}

// The files the repository holds: git's list where the tree is a git checkout, else every file below the root
// but .git and the build directories (.gitignore's build*/).
inline std::vector<std::filesystem::path> repository_files() {
  std::vector<std::filesystem::path> files;
  const Output listed = output_of(std::string("git -C ").append(quoted(root)).append(" ls-files -z 2>/dev/null"));
  if (listed.status == 0 && !listed.text.empty()) {
    for (std::size_t at = 0; at < listed.text.size();) {
      const std::size_t end = listed.text.find('\0', at);
      files.emplace_back(listed.text.substr(at, end - at));
      at = end == std::string::npos ? listed.text.size() : end + 1;
    }
    return files;
  }
  for (auto entry = std::filesystem::recursive_directory_iterator(root);
       entry != std::filesystem::recursive_directory_iterator(); ++entry) {
    const std::string name = entry->path().filename().string();
    if (entry->is_directory() && (name == ".git" || (entry.depth() == 0 && name.starts_with("build")))) {
      entry.disable_recursion_pending();
    } else if (entry->is_regular_file()) {
      files.push_back(std::filesystem::relative(entry->path(), root));
    }
  }
  return files;
}

// README.md and every docs/*.md.
inline std::vector<std::filesystem::path> markdown_docs() {
  std::vector<std::filesystem::path> docs{"README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") docs.push_back(std::filesystem::relative(entry.path(), root));
  std::sort(docs.begin(), docs.end());
  return docs;
}

}  // namespace circles::testing
