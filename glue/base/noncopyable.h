// tiershade base: NonCopyable, the base of the classes that own GL objects, files or threads and
// so must not be copied (the deleted copy constructor and assignment, written once).
#pragma once

struct NonCopyable {
  NonCopyable() = default;
  NonCopyable(const NonCopyable &) = delete;
  NonCopyable &operator=(const NonCopyable &) = delete;
};
