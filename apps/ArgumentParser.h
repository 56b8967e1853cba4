#pragma once
// The one argument loop of rmfx's commands: flags (--quiet), options whose value is the next
// argument (--out DIR, repeatable where the handler collects), arguments a handler reads itself
// (the media options), and positional arguments, in any order. Handlers return "" when the
// argument is fine, else the message the command prints after "rmfx COMMAND: ".

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rmfx::apps {

class ArgumentParser {
public:
    // "" or the message.
    using TakeValue = std::function<std::string(const std::string& value)>;
    // nullopt when args[i] is not the handler's; else "" or the message, with i moved past any
    // value the handler read.
    using TakeOwn = std::function<std::optional<std::string>(const std::vector<std::string>& args, size_t& i)>;

    // A flag: the argument alone.
    ArgumentParser& flag(std::initializer_list<const char*> names, std::function<void()> set);
    // An option with a value, the next argument: "NAME needs a value" when there is none, and
    // when it is empty unless `emptyValue` allows it.
    enum class EmptyValue { Refused, Allowed };
    ArgumentParser& option(std::initializer_list<const char*> names, TakeValue take,
                           EmptyValue emptyValue = EmptyValue::Refused);
    // Arguments the handler recognises itself (`names`, for names()); handlers are asked first,
    // in the order given.
    ArgumentParser& own(TakeOwn take, std::initializer_list<const char*> names = {});
    // Every argument that does not start with '-' (an empty one included).
    ArgumentParser& positional(TakeValue take);
    // What follows "unknown option 'X'" in that message; default " (see rmfx --help)".
    ArgumentParser& unknownOptionHint(std::string hint);

    // Takes every argument in order; "" when all were fine, else the first message.
    std::string parse(const std::vector<std::string>& args) const;

    // Every option and flag name the parser takes, in the order declared (rmfx --options).
    std::vector<std::string> names() const;

private:
    struct Named {
        std::vector<std::string> names;
        bool takesValue = false;
        EmptyValue emptyValue = EmptyValue::Refused;
        std::function<void()> set;
        TakeValue take;
    };
    const Named* find(const std::string& arg) const;

    std::vector<Named> named_;
    std::vector<TakeOwn> own_;
    std::vector<std::string> ownNames_;
    TakeValue positional_;
    std::string unknownHint_ = " (see rmfx --help)";
};

}  // namespace rmfx::apps
