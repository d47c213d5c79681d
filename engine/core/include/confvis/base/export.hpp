#pragma once
// CONFVIS_API marks the public API: every public header opens its namespace as
// `namespace confvis CONFVIS_API {`. Shared libraries (CMake option CONFVIS_SHARED_LIBS) are
// compiled with hidden visibility, so they export what these namespaces declare (functions,
// classes with their vtables and type info, which exceptions such as confvis::Error need across
// the library boundary) and nothing of the internals declared in the sources' own headers.
// Static libraries are unaffected. GCC and Clang (the attribute on each namespace: Clang does not
// carry it into nested ones).
//
// Thread-safety: a macro; nothing to share.
#if defined(__GNUC__) || defined(__clang__)
#define CONFVIS_API __attribute__((visibility("default")))
#else
#define CONFVIS_API
#endif
