#include "apps/ArgumentParser.h"

#include <algorithm>

namespace rmfx::apps {

ArgumentParser& ArgumentParser::flag(std::initializer_list<const char*> names, std::function<void()> set) {
    named_.push_back({{names.begin(), names.end()}, false, EmptyValue::Refused, std::move(set), {}});
    return *this;
}

ArgumentParser& ArgumentParser::option(std::initializer_list<const char*> names, TakeValue take, EmptyValue emptyValue) {
    named_.push_back({{names.begin(), names.end()}, true, emptyValue, {}, std::move(take)});
    return *this;
}

ArgumentParser& ArgumentParser::own(TakeOwn take, std::initializer_list<const char*> names) {
    own_.push_back(std::move(take));
    ownNames_.insert(ownNames_.end(), names.begin(), names.end());
    return *this;
}

std::vector<std::string> ArgumentParser::names() const {
    std::vector<std::string> out = ownNames_;
    for (const Named& n : named_) out.insert(out.end(), n.names.begin(), n.names.end());
    return out;
}

ArgumentParser& ArgumentParser::positional(TakeValue take) {
    positional_ = std::move(take);
    return *this;
}

ArgumentParser& ArgumentParser::unknownOptionHint(std::string hint) {
    unknownHint_ = std::move(hint);
    return *this;
}

const ArgumentParser::Named* ArgumentParser::find(const std::string& arg) const {
    for (const Named& n : named_)
        if (std::find(n.names.begin(), n.names.end(), arg) != n.names.end()) return &n;
    return nullptr;
}

std::string ArgumentParser::parse(const std::vector<std::string>& args) const {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        bool taken = false;
        for (const TakeOwn& take : own_) {
            if (auto message = take(args, i)) {
                if (!message->empty()) return *message;
                taken = true;
                break;
            }
        }
        if (taken) continue;
        if (const Named* n = find(arg)) {
            if (!n->takesValue) {
                n->set();
                continue;
            }
            if (i + 1 >= args.size() || (args[i + 1].empty() && n->emptyValue == EmptyValue::Refused))
                return arg + " needs a value";
            if (std::string message = n->take(args[++i]); !message.empty()) return message;
        } else if (!arg.empty() && arg[0] == '-') {
            return "unknown option '" + arg + "'" + unknownHint_;
        } else if (!positional_) {
            return "unexpected argument '" + arg + "'";
        } else if (std::string message = positional_(arg); !message.empty()) {
            return message;
        }
    }
    return "";
}

}  // namespace rmfx::apps
