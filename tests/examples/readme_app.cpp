// The README's application, "Using confvis in an application", exactly as the README shows it:
// its frame loop (runDisplay) and its main, extracted at build time (examples.cmake).
#include "readme_loop.inc"
#include "readme_main.inc"
