// A command run in this process with a pipeline of the test's own (a fake stage or percept kind
// added), its output captured: what the fake-stage and fake-percept suites check.
#pragma once

#include "commands/commands.h"
#include "visioncore/framework/controller.h"

#include <QStringList>

#include <sstream>
#include <string>

namespace fieldsight::test {

struct CommandOutcome
{
    int status = -1;
    std::string out;
    std::string err;
};

/// `fieldsight ARGS...` run in process with `pipeline`.
inline CommandOutcome runInProcess(const Pipeline& pipeline, const QStringList& args)
{
    std::ostringstream out, err;
    const cli::Context ctx{pipeline, out, err};
    CommandOutcome o;
    o.status = cli::runHeadless(args.value(0), QStringList{"fieldsight"} + args.mid(1), ctx);
    o.out = out.str();
    o.err = err.str();
    return o;
}

} // namespace fieldsight::test
