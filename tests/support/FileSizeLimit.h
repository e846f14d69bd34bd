#pragma once

// A file system that fails writes, for as long as the object lives: the process may not
// extend any regular file beyond `bytes` (RLIMIT_FSIZE; SIGXFSZ ignored, so the write fails
// with EFBIG instead of ending the process). Pipes and terminals are not limited, so the test's
// own output goes on. Stands in for a full disk where a test cannot mount one.
#include <csignal>
#include <sys/resource.h>

namespace opentop::test {

class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        ::getrlimit(RLIMIT_FSIZE, &m_before);
        m_handler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = m_before;
        limit.rlim_cur = bytes;
        m_ok = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit()
    {
        ::setrlimit(RLIMIT_FSIZE, &m_before);
        std::signal(SIGXFSZ, m_handler);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;
    bool ok() const { return m_ok; }

private:
    rlimit m_before{};
    void (*m_handler)(int) = nullptr;
    bool m_ok = false;
};

} // namespace opentop::test
