#pragma once

// A page under test on a one-drive simulated bus, with its parameters read once.
#include "model/session/DeviceParameters.h"
#include "tests/model/DriveSimFixture.h"
#include "ui/workspace/ParameterPage.h"

namespace opentop::test {

template <typename Page> class PageFixture : public DriveSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1"));
        parameters = std::make_unique<DeviceParameters>(session(1));
        page = std::make_unique<Page>(parameters.get());
        page->show();
        ASSERT_TRUE(run([this] { page->refresh(); }));
    }

    void TearDown() override
    {
        page.reset();
        parameters.reset();
        DriveSimFixture::TearDown();
    }

    // Starts a page operation (refresh, write) and waits for it to finish.
    bool run(const std::function<void()>& start)
    {
        bool finished = false;
        const auto c = QObject::connect(page.get(), &ParameterPage::operationFinished,
                                        [&finished] { finished = true; });
        start();
        const bool ok = waitUntil([&finished] { return finished; }, 10000);
        QObject::disconnect(c);
        return ok;
    }

    std::unique_ptr<DeviceParameters> parameters;
    std::unique_ptr<Page> page;
};

} // namespace opentop::test
