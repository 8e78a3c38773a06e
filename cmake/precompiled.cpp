// Empty on purpose: the source of the targets that hold a shared precompiled header
// (springcheck_precompile_holder in the top CMakeLists.txt); the header is built for it, and the
// targets compiled with the same flags reuse it.
