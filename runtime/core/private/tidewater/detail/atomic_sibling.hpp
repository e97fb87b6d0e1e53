// Where outputs that appear whole or not at all are made: a sibling of the target named
// after it and the writing process (TARGET.tmp-PID), renamed onto the target when done;
// a folder being replaced waits as TARGET.old-PID until its successor is in place.
// A process killed part-way leaves its siblings behind: the next writer of the same
// target removes those of processes that are gone (a live process's are another writer
// at work and stay). Internal: not part of the API. Threading: reentrant; two threads
// of one process must not write the same target at once.
#pragma once

#include <filesystem>

namespace tidewater::detail {

/// TARGET.tmp-PID for this process. Writers of a user's output sweep its stale siblings
/// first (sweep_stale_siblings); files inside a temporary folder need not.
std::filesystem::path temporary_sibling(const std::filesystem::path& target);

/// TARGET.old-PID for this process: where a replaced folder waits.
std::filesystem::path replaced_sibling(const std::filesystem::path& target);

/// Removes TARGET.tmp-N and TARGET.old-N where process N is gone (one read of the
/// target's folder; nothing else there is touched). Where the target is
/// missing and such a TARGET.old-N remains (its writer was killed between taking the old
/// folder away and putting the new one in place), that is the previous complete output:
/// it is put back first.
void sweep_stale_siblings(const std::filesystem::path& target);

}  // namespace tidewater::detail
