// tests/report/page/browser.hpp — a headless Chromium driven through the DevTools
// protocol, for testing the report's pages in a real browser.
//
//     browser b(AOGEN_CHROMIUM);                 // starts it; the destructor ends it
//     b.open("file:///tmp/report.html");         // waits for the load event
//     nlohmann::json n = b.evaluate("document.querySelectorAll('.point').length");
//     b.mouse_move(x, y);                        // real input events, as a mouse makes them
//     std::string png = b.screenshot(1280, 800);
//     b.errors()                                 // console errors and uncaught exceptions so far
//
// The protocol runs over a pipe (--remote-debugging-pipe: commands on the child's fd 3,
// replies and events on its fd 4, each message JSON ended by a NUL byte), so there is no
// port to find and no WebSocket to speak. Every wait has a deadline: a browser that hangs
// fails the test, it does not hang it.
#pragma once

#include <aogen/error.hpp>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace aogen_test {

class browser {
public:
    explicit browser(const std::string& chromium, std::chrono::seconds timeout = std::chrono::seconds(30)) : timeout_(timeout)
    {
        if (chromium.empty())
            aogen::fail("chromium", "was not found when the tests were configured", "valid: Debian's chromium (scripts/install-deps.sh installs it)");
        char profile[] = "/tmp/aogen_browser.XXXXXX";
        if (!::mkdtemp(profile)) aogen::fail("chromium", "no profile folder: " + std::string(std::strerror(errno)), "valid: a writable /tmp");
        profile_ = profile;
        std::signal(SIGPIPE, SIG_IGN); // a browser that died is an error from write(), not the end of the test
        int to_child[2], from_child[2];
        if (::pipe(to_child) != 0 || ::pipe(from_child) != 0) aogen::fail("chromium", "no pipe", "valid: free file descriptors");
        pid_ = ::fork();
        if (pid_ == 0) {
            // fds 3 and 4 are the protocol's; everything else the child prints is dropped.
            ::dup2(to_child[0], 3), ::dup2(from_child[1], 4);
            for (int fd : {to_child[0], to_child[1], from_child[0], from_child[1]})
                if (fd > 4) ::close(fd);
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1), ::dup2(null, 2);
            const std::string user_data = "--user-data-dir=" + profile_;
            std::vector<const char*> argv{chromium.c_str(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                                          "--hide-scrollbars", "--remote-debugging-pipe", user_data.c_str(), "about:blank", nullptr};
            ::execv(chromium.c_str(), const_cast<char* const*>(argv.data()));
            ::_exit(127);
        }
        ::close(to_child[0]), ::close(from_child[1]);
        write_fd_ = to_child[1], read_fd_ = from_child[0];
        const std::string target = call_browser("Target.createTarget", {{"url", "about:blank"}})["targetId"];
        session_ = call_browser("Target.attachToTarget", {{"targetId", target}, {"flatten", true}})["sessionId"];
        for (const char* domain : {"Runtime.enable", "Log.enable", "Page.enable"}) call(domain);
    }

    ~browser()
    {
        if (pid_ > 0) {
            ::close(write_fd_), ::close(read_fd_); // Chromium exits when its pipe closes
            for (int i = 0; i < 50 && ::waitpid(pid_, nullptr, WNOHANG) == 0; ++i) ::usleep(100000);
            if (::waitpid(pid_, nullptr, WNOHANG) == 0) ::kill(pid_, SIGKILL), ::waitpid(pid_, nullptr, 0);
        }
        std::error_code ec;
        std::filesystem::remove_all(profile_, ec);
    }
    browser(const browser&) = delete;
    browser& operator=(const browser&) = delete;

    // A command to the page's session; its result, or an aogen::error with the protocol's message.
    nlohmann::json call(const std::string& method, const nlohmann::json& params = nlohmann::json::object())
    {
        return send_and_wait(method, params, session_);
    }

    // Loads `url` and waits for its load event.
    void open(const std::string& url)
    {
        loaded_ = false;
        call("Page.navigate", {{"url", url}});
        wait_until([&] { return loaded_; }, "the load event of " + url);
    }

    // The value of a JavaScript expression (a promise is awaited); a thrown exception is an error.
    nlohmann::json evaluate(const std::string& expression)
    {
        const nlohmann::json r = call("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}});
        if (r.contains("exceptionDetails"))
            aogen::fail("page script", aogen::quote(expression) + " threw: " + r["exceptionDetails"].dump(), "valid: an expression that runs");
        return r["result"].value("value", nlohmann::json());
    }

    // The mouse moved to (x, y) in CSS pixels of the viewport, or a click there.
    void mouse_move(double x, double y) { call("Input.dispatchMouseEvent", {{"type", "mouseMoved"}, {"x", x}, {"y", y}}); }
    void click(double x, double y)
    {
        mouse_move(x, y);
        for (const char* type : {"mousePressed", "mouseReleased"})
            call("Input.dispatchMouseEvent", {{"type", type}, {"x", x}, {"y", y}, {"button", "left"}, {"clickCount", 1}});
    }

    // A PNG of the viewport at width × height CSS pixels.
    std::string screenshot(int width, int height)
    {
        call("Emulation.setDeviceMetricsOverride", {{"width", width}, {"height", height}, {"deviceScaleFactor", 1}, {"mobile", false}});
        const std::string encoded = call("Page.captureScreenshot", {{"format", "png"}})["data"];
        return decode_base64(encoded);
    }

    // Console errors, uncaught exceptions and error log entries seen so far.
    const std::vector<std::string>& errors()
    {
        drain();
        return errors_;
    }

private:
    nlohmann::json call_browser(const std::string& method, const nlohmann::json& params) { return send_and_wait(method, params, ""); }

    nlohmann::json send_and_wait(const std::string& method, const nlohmann::json& params, const std::string& session)
    {
        nlohmann::json message{{"id", ++last_id_}, {"method", method}, {"params", params}};
        if (!session.empty()) message["sessionId"] = session;
        const std::string text = message.dump() + '\0';
        for (size_t done = 0; done < text.size();) {
            const ssize_t n = ::write(write_fd_, text.data() + done, text.size() - done);
            if (n < 0 && errno != EINTR) aogen::fail("chromium", "the protocol pipe closed while sending " + method, "valid: a running browser");
            if (n > 0) done += size_t(n);
        }
        const int id = last_id_;
        nlohmann::json reply;
        wait_until([&] {
            for (auto it = replies_.begin(); it != replies_.end(); ++it)
                if ((*it)["id"] == id) {
                    reply = *it;
                    replies_.erase(it);
                    return true;
                }
            return false;
        }, "the reply to " + method);
        if (reply.contains("error")) aogen::fail(method, reply["error"].dump(), "valid: a command the browser accepts");
        return reply.value("result", nlohmann::json::object());
    }

    // Reads messages until `done()` holds, or fails at the deadline.
    template <typename F>
    void wait_until(F done, const std::string& what)
    {
        const auto deadline = std::chrono::steady_clock::now() + timeout_;
        while (!done()) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
            if (left <= 0) aogen::fail("chromium", "no " + what + " within " + std::to_string(timeout_.count()) + " s", "valid: a browser that answers");
            read_some(int(left));
        }
    }

    void drain()
    {
        while (read_some(0)) {}
    }

    // Reads what is there within `wait_ms`; false when nothing came.
    bool read_some(int wait_ms)
    {
        pollfd p{read_fd_, POLLIN, 0};
        if (::poll(&p, 1, wait_ms) <= 0) return false;
        char chunk[65536];
        const ssize_t n = ::read(read_fd_, chunk, sizeof chunk);
        if (n == 0) aogen::fail("chromium", "exited (its protocol pipe closed)", "valid: a running browser");
        if (n < 0) return errno == EINTR;
        buffer_.append(chunk, size_t(n));
        for (size_t end; (end = buffer_.find('\0')) != std::string::npos;) {
            handle(nlohmann::json::parse(buffer_.substr(0, end)));
            buffer_.erase(0, end + 1);
        }
        return true;
    }

    void handle(const nlohmann::json& m)
    {
        if (m.contains("id")) return replies_.push_back(m);
        const std::string method = m.value("method", "");
        const nlohmann::json& p = m.contains("params") ? m["params"] : nlohmann::json::object();
        if (method == "Page.loadEventFired") loaded_ = true;
        else if (method == "Runtime.exceptionThrown") errors_.push_back("exception: " + p["exceptionDetails"].dump());
        else if (method == "Runtime.consoleAPICalled" && (p.value("type", "") == "error" || p.value("type", "") == "assert"))
            errors_.push_back("console." + p.value("type", "") + ": " + p["args"].dump());
        else if (method == "Log.entryAdded" && p["entry"].value("level", "") == "error")
            errors_.push_back("log: " + p["entry"].value("text", "") + " (" + p["entry"].value("url", "") + ")");
    }

    static std::string decode_base64(const std::string& text)
    {
        std::string out;
        uint32_t bits = 0;
        int count = 0;
        for (char c : text) {
            const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
            const char* at = c ? std::strchr(digits, c) : nullptr;
            if (!at) continue; // '=' and line breaks
            bits = bits << 6 | uint32_t(at - digits), count += 6;
            if (count >= 8) out += char((bits >> (count - 8)) & 0xff), count -= 8;
        }
        return out;
    }

    std::chrono::seconds timeout_;
    std::string profile_, session_, buffer_;
    pid_t pid_ = -1;
    int write_fd_ = -1, read_fd_ = -1, last_id_ = 0;
    bool loaded_ = false;
    std::vector<nlohmann::json> replies_;
    std::vector<std::string> errors_;
};

} // namespace aogen_test
