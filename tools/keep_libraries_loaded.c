/* Preloaded into sanitizer runs (tools/sanitize): a dlclose that unloads nothing, so that
   LeakSanitizer, which reports at exit, can still name the library that allocated a leak.
   The Vulkan and OpenCL loaders unload their drivers first, which left their leaks as
   "<unknown module>", beyond tools/lsan.supp's suppressions by library. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
