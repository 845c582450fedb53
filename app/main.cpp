#include "app/version.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--version") == 0) {
        std::printf("glint %s\n", glint::kVersion);
        return 0;
    }
    std::fprintf(stderr, "glint: usage: glint [--version]\n");
    return 2;
}
