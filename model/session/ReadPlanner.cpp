#include "model/session/ReadPlanner.h"

#include <algorithm>

namespace opentop {

namespace {

const ReadBlock* blockFor(const Profile& profile, const ParameterMeta& p)
{
    for (const ReadBlock& b : profile.readBlocks) {
        if (b.function == p.readFunction && p.address >= b.first &&
            p.address + p.registerCount - 1 <= b.last)
            return &b;
    }
    return nullptr;
}

ReadBlockPlan single(const ParameterMeta* p)
{
    return ReadBlockPlan{p->readFunction, p->address, quint16(p->registerCount), {p}};
}

} // namespace

QVector<ReadBlockPlan> ReadPlanner::singles(const QVector<const ParameterMeta*>& parameters)
{
    QVector<ReadBlockPlan> plans;
    for (const ParameterMeta* p : parameters) {
        if (p->isReadable())
            plans << single(p);
    }
    return plans;
}

QVector<ReadBlockPlan> ReadPlanner::plan(const Profile& profile,
                                         QVector<const ParameterMeta*> parameters)
{
    parameters.erase(std::remove_if(parameters.begin(), parameters.end(),
                                    [](const ParameterMeta* p) { return !p->isReadable(); }),
                     parameters.end());
    std::sort(parameters.begin(), parameters.end(),
              [](const ParameterMeta* a, const ParameterMeta* b) {
                  return a->readFunction != b->readFunction ? a->readFunction < b->readFunction
                                                            : a->address < b->address;
              });
    QVector<ReadBlockPlan> plans;
    for (int i = 0; i < parameters.size();) {
        const ParameterMeta* first = parameters[i];
        const ReadBlock* block = blockFor(profile, *first);
        ReadBlockPlan plan = single(first);
        ++i;
        if (block) {
            while (i < parameters.size()) {
                const ParameterMeta* next = parameters[i];
                const int end = next->address + next->registerCount;
                if (next->readFunction != first->readFunction ||
                    blockFor(profile, *next) != block ||
                    end - plan.address > profile.maxReadRegisters)
                    break;
                plan.count = quint16(std::max<int>(plan.count, end - plan.address));
                plan.parameters << next;
                ++i;
            }
        }
        plans << plan;
    }
    return plans;
}

} // namespace opentop
