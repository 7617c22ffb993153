// Points LeakSanitizer at tests/render/lsan.supp (leaks inside Mesa's OSMesa, see there) for the
// test executables that create GL contexts. Without a sanitizer nobody calls this function.
extern "C" const char* __lsan_default_options();

extern "C" const char* __lsan_default_options() {
  return "suppressions=" FRICTIONLAB_TEST_SOURCE_DIR "/tests/render/lsan.supp";
}
