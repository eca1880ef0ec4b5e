#ifndef SCOUT_APPS_SCOUT_BUILD_COMMIT_H_
#define SCOUT_APPS_SCOUT_BUILD_COMMIT_H_

namespace scout::apps {

// The commit this binary was built from: 12 hex digits, followed by
// " +modified" when the sources differed from it, or "unknown" when it was not
// built from a git checkout. Written at every build by
// cmake/build_commit.cmake.
const char* BuildCommit();

}  // namespace scout::apps

#endif  // SCOUT_APPS_SCOUT_BUILD_COMMIT_H_
