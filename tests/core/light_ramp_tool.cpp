// Not a test: writes a stream lit by a ramping light (support/light_ramp.h), for measuring how
// the table follows it on real frames. light_ramp STREAM OUT R G B (the gains at the last frame).
#include "support/light_ramp.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
    if (argc != 6) {
        std::fprintf(stderr, "usage: light_ramp STREAM OUT R G B\n");
        return 2;
    }
    const std::array<double, 3> gain{std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5])};
    for (double g : gain)
        if (!(g > 0.05 && g < 20)) {
            std::fprintf(stderr, "light_ramp: gains must be from 0.05 to 20\n");
            return 2;
        }
    const QString problem = fieldsight::test::writeLightRamp(argv[1], argv[2], gain);
    if (!problem.isEmpty()) {
        std::fprintf(stderr, "light_ramp: %s\n", qPrintable(problem));
        return 1;
    }
    return 0;
}
