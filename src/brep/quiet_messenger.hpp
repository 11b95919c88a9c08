// OCCT's default messenger silenced while a QuietMessenger lives (its data exchange prints
// statistics to stdout, which a command-line tool writes its JSON to), and the lock that keeps
// OCCT's data exchange (process-wide parameters, the messenger) to one thread at a time.
#pragma once

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>

#include <mutex>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Held around every use of OCCT's STEP and IGES readers and writers: their parameters
/// (Interface_Static) and the default messenger are process-wide.
inline std::mutex& dataExchangeMutex()
{
    static std::mutex m;
    return m;
}

/// Silences OCCT's default messenger while it lives (hold dataExchangeMutex()); the printers' levels are restored after.
class QuietMessenger {
public:
    QuietMessenger()
    {
        const Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->Printers();
        for (int k = 1; k <= printers.Length(); ++k) {
            levels_.push_back(printers(k)->GetTraceLevel());
            printers(k)->SetTraceLevel(Message_Fail);
        }
    }
    ~QuietMessenger()
    {
        const Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->Printers();
        for (int k = 1; k <= printers.Length() && k <= static_cast<int>(levels_.size()); ++k)
            printers(k)->SetTraceLevel(levels_[static_cast<std::size_t>(k - 1)]);
    }
    QuietMessenger(const QuietMessenger&) = delete;
    QuietMessenger& operator=(const QuietMessenger&) = delete;

private:
    std::vector<Message_Gravity> levels_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
