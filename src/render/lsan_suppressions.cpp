// Compiled into every program that links contactfx::render, in sanitizer builds only
// (CONTACTFX_SANITIZE). Cairo draws text through fontconfig, which keeps its font caches until the
// process ends; LeakSanitizer reports them as leaks at exit. They are fontconfig's, not ours, so they are
// suppressed by library name: a leak of our own still fails the build. Weak, so that several copies (or an
// application's own list) can coexist.
extern "C" __attribute__((weak)) const char* __lsan_default_suppressions()
{
    return "leak:libfontconfig.so\n";
}

// Keeps the table of used suppressions out of the programs' output.
extern "C" __attribute__((weak)) const char* __lsan_default_options()
{
    return "print_suppressions=0";
}
