// Every kernel's plan, derivation by derivation (verify/choice.h, plan_kernels): each taken
// from the cache where a choice was measured before for the same kernel and build, the
// others measured here or as tasks of a runner, in other processes.
#include "verify/choice.h"

#include "cache/store.h"

#include <fmt/format.h>

#include <memory>
#include <optional>

namespace impact::verify {

std::vector<kernel_plan> plan_kernels(const engine::library& lib, cache::store* store,
                                      const std::function<void(std::size_t, std::size_t)>& done,
                                      const task_runner& runner)
{
    struct pending {
        const engine::kernel* kernel;
        const engine::term_order* order;
        std::string key;
        std::optional<kernel_plan> plan;
    };
    // Each derivation's term order, kept while its kernels are planned (printing with it
    // makes a form's text the same in every process and run).
    std::vector<std::unique_ptr<engine::term_order>> orders;
    std::vector<pending> kernels;
    for (const engine::derivation* d : lib.in_order()) {
        orders.push_back(std::make_unique<engine::term_order>(engine::declaration_order(d->symbols)));
        for (const engine::kernel& k : d->kernels) {
            kernels.push_back({&k, orders.back().get(), {}, std::nullopt});
            for (const engine::kernel& fixed : k.limits)   // its fixed spheres' kernels after it
                kernels.push_back({&fixed, orders.back().get(), {}, std::nullopt});
        }
    }
    std::size_t finished = 0;
    auto one_done = [&] {
        ++finished;
        if (done)
            done(finished, kernels.size());
    };
    // The cache first: a choice measured before for the same kernel and build.
    std::vector<std::size_t> to_measure;
    for (std::size_t i = 0; i < kernels.size(); ++i) {
        pending& p = kernels[i];
        if (store) {
            p.key = choice_key(*p.kernel, *p.order);
            if (const auto text = store->get("kernel choice", p.key))
                p.plan = decode_choice(*text, *p.kernel, *p.order);
        }
        if (p.plan)
            one_done();
        else
            to_measure.push_back(i);
    }
    auto keep = [&](pending& p) {
        if (store)
            store->put("kernel choice", p.key, encode_choice(*p.plan, *p.order));
    };
    if (!runner || to_measure.size() < 2) {
        for (std::size_t i : to_measure) {
            pending& p = kernels[i];
            p.plan = plan_kernel(*p.kernel, *p.order);
            keep(p);
            one_done();
        }
    } else {
        std::vector<text_task> tasks;
        for (std::size_t i : to_measure) {
            const pending& p = kernels[i];
            // Its cost guessed from the text of everything it measures (its forms, their size).
            const std::size_t cost = p.key.empty() ? choice_key(*p.kernel, *p.order).size() : p.key.size();
            tasks.push_back({fmt::format("kernel '{}'", p.kernel->name), p.kernel->where,
                             [&p] { return encode_choice(plan_kernel(*p.kernel, *p.order), *p.order); }, cost,
                             "choosing its forms", "choose them"});
        }
        const std::vector<std::string> texts = runner(tasks, one_done);
        for (std::size_t t = 0; t < to_measure.size(); ++t) {
            pending& p = kernels[to_measure[t]];
            p.plan = decode_choice(texts.at(t), *p.kernel, *p.order);
            if (!p.plan)
                throw error(p.kernel->where, fmt::format("kernel '{}': the choice of its forms came back from its "
                                                         "worker process unreadable",
                                                         p.kernel->name));
            keep(p);
        }
    }
    std::vector<kernel_plan> plans;
    for (pending& p : kernels)
        plans.push_back(std::move(*p.plan));
    return plans;
}

} // namespace impact::verify
