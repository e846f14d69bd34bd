// Retries on a noisy line (issue 11, item 2): the defaults, and the extra attempts once a
// request needed a retry to succeed, through the real client worker.
#include "transport/RetryPolicy.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/ConnectionSettings.h"
#include "transport/ModbusClient.h"
#include "transport/RtuFrame.h"

#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

ModbusResult answered(int attempts)
{
    ModbusResult r;
    r.error = attempts > 0 ? ModbusError::Ok : ModbusError::Timeout;
    r.attempts = attempts > 0 ? attempts : 4;
    return r;
}

} // namespace

TEST(RetryPolicyTest, DefaultsFinishOnANoisyLine)
{
    const ConnectionSettings s;
    EXPECT_EQ(s.timeoutMs, 200);
    EXPECT_EQ(s.retries, 3);
}

TEST(RetryPolicyTest, ARecoveredRequestMakesTheLineNoisyForAWhile)
{
    RetryPolicy policy;
    EXPECT_EQ(policy.retriesFor(-1, 3), 3);
    policy.record(answered(1));
    EXPECT_FALSE(policy.noisy());
    policy.record(answered(2)); // needed a retry
    EXPECT_TRUE(policy.noisy());
    EXPECT_EQ(policy.retriesFor(-1, 3), 5);
    EXPECT_EQ(policy.retriesFor(-1, 9), RetryPolicy::kMaxRetries);
    EXPECT_EQ(policy.retriesFor(0, 3), 0);  // a request's own count stays
    EXPECT_EQ(policy.retriesFor(-1, 0), 0); // so does "no retries" for the connection
    for (int i = 0; i < RetryPolicy::kMemory; ++i)
        policy.record(answered(1));
    EXPECT_FALSE(policy.noisy());
}

TEST(RetryPolicyTest, AnAbsentDriveDoesNotMakeTheLineNoisy)
{
    RetryPolicy policy;
    for (int i = 0; i < 5; ++i)
        policy.record(answered(0)); // never answers
    EXPECT_FALSE(policy.noisy());
    EXPECT_EQ(policy.retriesFor(-1, 3), 3);
}

TEST(RetryPolicyTest, ClientGivesMoreAttemptsOnceTheLineProvedNoisy)
{
    // One retry configured. The first read succeeds at its second attempt; the second read's
    // drive then misses three replies in a row: it still gets its answer at the fourth.
    ConnectionSettings settings;
    settings.retries = 1;
    auto calls = std::make_shared<std::atomic<int>>(0);
    MockClient f(
        [calls](const QByteArray& adu) {
            const int n = ++*calls;
            return n == 1 || (n >= 3 && n <= 5) ? QByteArray() : echoDevice(adu);
        },
        settings);
    ModbusResult r = f.client->execute(ModbusRequest::readHolding(1, 7, 1));
    EXPECT_EQ(r.error, ModbusError::Ok);
    EXPECT_EQ(r.attempts, 2);
    r = f.client->execute(ModbusRequest::readHolding(1, 8, 1));
    EXPECT_EQ(r.error, ModbusError::Ok) << r.errorText().toStdString();
    EXPECT_EQ(r.attempts, 4);
    EXPECT_EQ(r.registers, QVector<quint16>({8}));
}
