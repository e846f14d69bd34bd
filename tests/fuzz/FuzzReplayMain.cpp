// A stand-in for libFuzzer's main, so that every harness also runs as a plain test wherever the
// suite is built (GCC, no OPENTOP_FUZZ): each seed input is given to LLVMFuzzerTestOneInput, then
// a fixed number of mutations of them from a fixed random seed (bit flips, bytes set, inserted
// and erased, chunks copied, corpus files spliced, truncation, dictionary tokens, numbers
// replaced), until a time bound. Nothing guides the mutations: this keeps the harnesses building
// and catches a decoder that falls over near its seeds; finding deep bugs is scripts/fuzz.sh's
// job. A crash, trap or sanitizer report ends the process (the test fails) and leaves the
// input in <harness>-crash-<number> in the working folder; run the harness on that file to
// reproduce.
//   HARNESS [--seed N] [--mutations N] [--seconds S] [--max-len N] [--dict FILE] CORPUS...
// CORPUS: folders (every file in them, by name) or files.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define OPENTOP_REPLAY_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define OPENTOP_REPLAY_SANITIZER 1
#endif
#endif
#ifdef OPENTOP_REPLAY_SANITIZER
#include <sanitizer/common_interface_defs.h>
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

using Bytes = std::vector<uint8_t>;

// The input under test, for the crash handlers (only async-signal-safe calls there).
const uint8_t* g_data = nullptr;
size_t g_size = 0;
char g_crashPath[512] = {};
struct sigaction g_previous[32];
const int kSignals[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};

void say(const char* text)
{
    const ssize_t written = ::write(STDERR_FILENO, text, std::strlen(text));
    static_cast<void>(written);
}

void saveInput()
{
    const int fd = ::open(g_crashPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        size_t done = 0;
        while (done < g_size) {
            const ssize_t n = ::write(fd, g_data + done, g_size - done);
            if (n <= 0)
                break;
            done += size_t(n);
        }
        ::close(fd);
    }
    say("\nfuzz replay: the input that failed is in ");
    say(g_crashPath);
    say("\n");
}

void onDeadlySignal(int sig)
{
    saveInput();
    // The previous handler (the sanitizer's, or the default) reports and ends the process.
    ::sigaction(sig, &g_previous[sig], nullptr);
    ::raise(sig);
}

void installCrashHandlers()
{
    for (int sig : kSignals) {
        struct sigaction action = {};
        action.sa_handler = onDeadlySignal;
        sigemptyset(&action.sa_mask);
        ::sigaction(sig, &action, &g_previous[sig]);
    }
#ifdef OPENTOP_REPLAY_SANITIZER
    __sanitizer_set_death_callback(saveInput); // a report ends the process without a signal
#endif
}

// splitmix64: the same sequence with every compiler and library, unlike <random>'s
// distributions.
class Random
{
public:
    explicit Random(uint64_t seed)
        : m_state(seed)
    {
    }
    uint64_t next()
    {
        uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    size_t below(size_t n) { return n == 0 ? 0 : size_t(next() % n); }
    bool oneIn(size_t n) { return below(n) == 0; }

private:
    uint64_t m_state;
};

struct Options
{
    uint64_t seed = 1;
    long mutations = 20000;
    double seconds = 4;
    size_t maxLength = 65536;
    std::string dictionary;
    std::vector<std::string> corpus;
};

bool readFile(const std::filesystem::path& path, Bytes* bytes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

// libFuzzer's dictionary format: name="value" lines with \\, \" and \xNN escapes; # comments.
std::vector<Bytes> readDictionary(const std::string& path, bool* ok)
{
    std::vector<Bytes> tokens;
    std::ifstream in(path);
    *ok = bool(in);
    std::string line;
    while (std::getline(in, line)) {
        const size_t open = line.find('"');
        const size_t close = line.rfind('"');
        if (line.empty() || line[0] == '#' || open == std::string::npos || close <= open)
            continue;
        Bytes token;
        for (size_t i = open + 1; i < close; ++i) {
            if (line[i] == '\\' && i + 1 < close && line[i + 1] == 'x' && i + 3 < close) {
                token.push_back(uint8_t(std::strtoul(line.substr(i + 2, 2).c_str(), nullptr, 16)));
                i += 3;
            } else if (line[i] == '\\' && i + 1 < close) {
                token.push_back(uint8_t(line[++i]));
            } else {
                token.push_back(uint8_t(line[i]));
            }
        }
        if (!token.empty())
            tokens.push_back(token);
    }
    return tokens;
}

class Mutator
{
public:
    Mutator(const std::vector<Bytes>& corpus, const std::vector<Bytes>& dictionary,
            size_t maxLength, uint64_t seed)
        : m_corpus(corpus)
        , m_dictionary(dictionary)
        , m_maxLength(maxLength)
        , m_random(seed)
    {
    }

    // A new input: the last one changed further (three times in four: chains of about four
    // steps go further from the seeds), or a seed afresh; 1–6 changes, now and then up to 32.
    Bytes next()
    {
        Bytes input = m_last.empty() || m_random.oneIn(4)
                          ? m_corpus[m_random.below(m_corpus.size())]
                          : m_last;
        const size_t changes = 1 + m_random.below(m_random.oneIn(8) ? 32 : 6);
        for (size_t i = 0; i < changes; ++i)
            mutate(&input);
        if (input.size() > m_maxLength)
            input.resize(m_maxLength);
        m_last = input;
        return input;
    }

private:
    void mutate(Bytes* b)
    {
        static const uint8_t interesting[] = {0x00, 0x01, 0x02, 0x7F, 0x80, 0xFE, 0xFF, '"', ',',
                                              ';',  '\n', '\r', '{',  '}',  '[',  ']',  ':', '\\'};
        const size_t at = m_random.below(b->size() + 1); // a position, the end included
        switch (m_random.below(11)) {
        case 0: // flip a bit
            if (!b->empty())
                (*b)[at % b->size()] ^= uint8_t(1u << m_random.below(8));
            break;
        case 1: // set a byte
            if (!b->empty())
                (*b)[at % b->size()] = m_random.oneIn(2)
                                           ? interesting[m_random.below(sizeof interesting)]
                                           : uint8_t(m_random.next());
            break;
        case 2: { // insert random bytes
            const size_t n = 1 + m_random.below(8);
            for (size_t i = 0; i < n; ++i)
                b->insert(b->begin() + long(at), uint8_t(m_random.next()));
            break;
        }
        case 3: { // erase a range
            const size_t n = std::min(b->size() - std::min(at, b->size()), 1 + m_random.below(16));
            b->erase(b->begin() + long(at), b->begin() + long(at + n));
            break;
        }
        case 4: { // copy a chunk of the input, or of another corpus file, to a position
            const Bytes& from = m_random.oneIn(2) ? *b : m_corpus[m_random.below(m_corpus.size())];
            if (from.empty())
                break;
            const size_t start = m_random.below(from.size());
            const size_t n = std::min(from.size() - start, 1 + m_random.below(64));
            const Bytes chunk(from.begin() + long(start), from.begin() + long(start + n));
            b->insert(b->begin() + long(at), chunk.begin(), chunk.end());
            break;
        }
        case 5: { // splice: this input's start, another file's end
            const Bytes& other = m_corpus[m_random.below(m_corpus.size())];
            const size_t from = m_random.below(other.size() + 1);
            b->resize(at);
            b->insert(b->end(), other.begin() + long(from), other.end());
            break;
        }
        case 6: // truncate
            b->resize(at);
            break;
        case 7: // insert a dictionary token
        case 8: // or overwrite with one
            if (!m_dictionary.empty()) {
                const Bytes& token = m_dictionary[m_random.below(m_dictionary.size())];
                if (m_random.oneIn(2))
                    b->erase(b->begin() + long(at),
                             b->begin() + long(std::min(b->size(), at + token.size())));
                b->insert(b->begin() + long(at), token.begin(), token.end());
            }
            break;
        case 9: // swap two bytes
            if (b->size() > 1)
                std::swap((*b)[at % b->size()], (*b)[m_random.below(b->size())]);
            break;
        default: // replace the next number with an edge of some range
            replaceNumber(b, at);
            break;
        }
    }

    void replaceNumber(Bytes* b, size_t at)
    {
        static const char* numbers[] = {
            "0",          "-1",    "1",      "65535", "65536", "-0",  "2147483648",
            "4294967296", "1e308", "1e-320", "NaN",   "0.5",   "1,5", "9223372036854775808",
            "00",         ""};
        auto isNumber = [](uint8_t c) {
            return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e';
        };
        size_t start = at;
        while (start < b->size() && !((*b)[start] >= '0' && (*b)[start] <= '9'))
            ++start;
        if (start == b->size())
            return;
        size_t end = start;
        while (end < b->size() && isNumber((*b)[end]))
            ++end;
        const char* text = numbers[m_random.below(std::size(numbers))];
        b->erase(b->begin() + long(start), b->begin() + long(end));
        b->insert(b->begin() + long(start), text, text + std::strlen(text));
    }

    const std::vector<Bytes>& m_corpus;
    const std::vector<Bytes>& m_dictionary;
    size_t m_maxLength;
    Random m_random;
    Bytes m_last;
};

void run(const Bytes& input)
{
    // libFuzzer hands a harness a buffer of exactly the input's size: so does this, so that a
    // read past the end is a sanitizer report and not a read of a vector's spare room.
    const Bytes exact(input.begin(), input.end());
    g_data = exact.data();
    g_size = exact.size();
    LLVMFuzzerTestOneInput(exact.data(), exact.size());
}

bool parseOptions(int argc, char** argv, Options* o)
{
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--seed" && hasValue)
            o->seed = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--mutations" && hasValue)
            o->mutations = std::strtol(argv[++i], nullptr, 10);
        else if (a == "--seconds" && hasValue)
            o->seconds = std::strtod(argv[++i], nullptr);
        else if (a == "--max-len" && hasValue)
            o->maxLength = std::strtoul(argv[++i], nullptr, 10);
        else if (a == "--dict" && hasValue)
            o->dictionary = argv[++i];
        else if (a.rfind("--", 0) == 0)
            return false;
        else
            o->corpus.push_back(a);
    }
    return !o->corpus.empty();
}

} // namespace

int main(int argc, char** argv)
{
    const std::string name = std::filesystem::path(argv[0]).filename().string();
    Options options;
    if (!parseOptions(argc, argv, &options)) {
        std::fprintf(stderr,
                     "usage: %s [--seed N] [--mutations N] [--seconds S] [--max-len N] "
                     "[--dict FILE] CORPUS...\n",
                     name.c_str());
        return 2;
    }
    std::vector<Bytes> corpus;
    for (const std::string& entry : options.corpus) {
        std::vector<std::filesystem::path> files;
        std::error_code error;
        if (std::filesystem::is_directory(entry, error)) {
            for (const auto& file : std::filesystem::directory_iterator(entry, error))
                if (file.is_regular_file())
                    files.push_back(file.path());
            std::sort(files.begin(), files.end()); // the same order, so the same mutations
        } else {
            files.push_back(entry);
        }
        for (const auto& file : files) {
            Bytes bytes;
            if (!readFile(file, &bytes)) {
                std::fprintf(stderr, "%s: cannot read %s\n", name.c_str(), file.c_str());
                return 1;
            }
            corpus.push_back(std::move(bytes));
        }
    }
    // A missing seed corpus would leave the test nothing to run: that is a failure.
    if (corpus.empty()) {
        std::fprintf(stderr, "%s: no seed inputs in the corpus given\n", name.c_str());
        return 1;
    }
    bool dictionaryRead = true;
    const std::vector<Bytes> dictionary = options.dictionary.empty()
                                              ? std::vector<Bytes>()
                                              : readDictionary(options.dictionary, &dictionaryRead);
    if (!dictionaryRead) {
        std::fprintf(stderr, "%s: cannot read %s\n", name.c_str(), options.dictionary.c_str());
        return 1;
    }

    installCrashHandlers();
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    long number = 0;
    auto crashPath = [&] {
        std::snprintf(g_crashPath, sizeof g_crashPath, "%s-crash-%ld", name.c_str(), number);
    };
    for (const Bytes& seed : corpus) {
        crashPath();
        run(seed);
        ++number;
    }
    Mutator mutator(corpus, dictionary, options.maxLength, options.seed);
    long mutations = 0;
    while (mutations < options.mutations && elapsed() < options.seconds) {
        const Bytes input = mutator.next();
        crashPath();
        run(input);
        ++number;
        ++mutations;
    }
    std::printf("%s: %zu seed inputs and %ld of %ld mutations (seed %llu) in %.2f s%s\n",
                name.c_str(), corpus.size(), mutations, options.mutations,
                static_cast<unsigned long long>(options.seed), elapsed(),
                mutations < options.mutations ? ", stopped at the time bound" : "");
    return 0;
}
