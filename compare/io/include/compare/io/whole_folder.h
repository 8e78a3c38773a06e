#pragma once
// A result folder holds one whole run or the previous one, never a mix: its files are written
// into a staging folder beside it, which then takes the folder's place in one step (Linux's
// renameat2 with RENAME_EXCHANGE swaps the two directories atomically), and the previous one is
// removed. Two runs into the same folder at once each swap in a whole folder: the last one wins.
// An interrupted or failed write leaves the previous folder as it was (and, at worst, a staging
// folder named .NAME.staging.* beside it).
#include <expected>
#include <functional>
#include <set>
#include <string>

namespace springcheck {

// The names a result folder of one kind may hold: files, and folders that are themselves result
// folders of another kind (a comparison's engine folders are run folders).
struct FolderKind {
  std::string what;              // "run folder", for messages
  std::set<std::string> files;   // the file names it writes
  const FolderKind* subfolders = nullptr;  // any folder inside must be of this kind
  // Numbered files it writes: PREFIX, digits, SUFFIX ("frame_", ".obj"); empty: none.
  std::string numbered_prefix, numbered_suffix;
};
const FolderKind& runFolderKind();         // final_state.csv, trajectory.npy, ... summary.json, obj/
const FolderKind& objSequenceKind();       // obj/: frame_NNNNN.obj, times.csv
const FolderKind& comparisonFolderKind();  // comparison.json, the tables, engine run folders

// Writes `path` whole: `body` fills the staging folder it is given (an empty, fresh folder); on
// success the staging folder replaces `path`. Refuses, before writing, a `path` that is not a
// folder or that holds anything `kind` does not write (so `--out` never replaces a folder of the
// user's), naming the first such entry.
[[nodiscard]] std::expected<void, std::string> writeFolderWhole(
    const std::string& path, const FolderKind& kind,
    const std::function<std::expected<void, std::string>(const std::string& staging)>& body);

}  // namespace springcheck
