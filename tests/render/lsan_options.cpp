// Points LeakSanitizer at tests/render/lsan.supp (leaks inside Mesa's OSMesa, see there) for the
// test executables that create GL contexts, and turns off its record of dynamic TLS: the EGL back
// end loads Mesa's swrast_dri.so and LLVM with dlopen, whose thread-local blocks GCC 12's runtime
// can misread into a range that is not memory, killing the leak check at exit (as in the
// frictionlab executable, src/lab/recorder/video_module_loader.cpp; docs/rendering.md). Without a
// sanitizer nobody calls this function.
extern "C" const char* __lsan_default_options();

extern "C" const char* __lsan_default_options() {
  return "suppressions=" FRICTIONLAB_TEST_SOURCE_DIR
         "/tests/render/lsan.supp:intercept_tls_get_addr=0";
}
