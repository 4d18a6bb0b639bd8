// `benchpilot-cli completion bash`: a bash completion script made from the
// command registry, so it never falls behind the commands.
#include "command.h"

#include <QCoreApplication>

namespace app::cli {
namespace {

QString longOptions(const QList<QCommandLineOption>& options)
{
    QStringList words;
    for (const auto& o : options)
        for (const QString& n : o.names())
            if (n.size() > 1)
                words << QStringLiteral("--") + n;
    return words.join(QLatin1Char(' '));
}

/// One `case` arm per command path: what may follow it.
void caseArms(const std::vector<Command>& list, const QString& prefix, const QString& global, QString& out)
{
    for (const auto& c : list) {
        const QString path = prefix.isEmpty() ? c.name : prefix + QLatin1Char(' ') + c.name;
        QString words;
        if (!c.subcommands.empty()) {
            QStringList subs;
            for (const auto& s : c.subcommands)
                subs << s.name;
            words = subs.join(QLatin1Char(' '));
            caseArms(c.subcommands, path, global, out);
        } else {
            words = longOptions(c.options) + QLatin1Char(' ') + global;
        }
        out += QStringLiteral("        \"%1\") words=\"%2 --help\" ;;\n").arg(path, words.trimmed());
    }
}

int run(Invocation& inv)
{
    const QStringList words = inv.arguments();
    if (words != QStringList{QStringLiteral("bash")})
        return inv.usage(QCoreApplication::translate("app::cli", "only 'bash' is supported: source <(benchpilot-cli completion bash)"));
    const QString global = longOptions(globalOptions());
    QStringList top;
    for (const auto& c : commands())
        top << c.name;
    QString arms;
    caseArms(commands(), QString(), global, arms);
    inv.out() << "# bash completion for benchpilot-cli: source <(benchpilot-cli completion bash)\n"
                 "_benchpilot_cli() {\n"
                 "    local cur prev path word words i\n"
                 "    cur=\"${COMP_WORDS[COMP_CWORD]}\"\n"
                 "    prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
                 "    case \"$prev\" in\n"
                 "        --sim|--instrument) COMPREPLY=($(compgen -W \"analyzer stage\" -- \"$cur\")); return ;;\n"
                 "        --port|--profile) COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n"
                 "    esac\n"
                 "    # The command path: the words so far that are not options or option values.\n"
                 "    path=\"\"\n"
                 "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
                 "        word=\"${COMP_WORDS[i]}\"\n"
                 "        case \"$word\" in\n"
                 "            --sim|--port|--baud|--timeout|--instrument|--profile) ((i++)) ;;\n"
                 "            -*) ;;\n"
                 "            *) if [[ -z \"$path\" ]]; then path=\"$word\"; else path=\"$path $word\"; fi ;;\n"
                 "        esac\n"
                 "    done\n"
                 "    case \"$path\" in\n"
                 "        \"\") words=\""
              << top.join(QLatin1Char(' ')) << " " << global << " --help --version\" ;;\n"
              << arms
              << "        *) words=\"\" ;;\n"
                 "    esac\n"
                 "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
                 "}\n"
                 "complete -o default -F _benchpilot_cli benchpilot-cli\n";
    inv.out().flush();
    return Ok;
}

} // namespace

void addCompletionCommand(std::vector<Command>& list)
{
    list.push_back({QStringLiteral("completion"), QCoreApplication::translate("app::cli", "print a bash completion script"),
                    QStringLiteral("bash"), QCoreApplication::translate("app::cli", "Use: source <(benchpilot-cli completion bash)"),
                    {}, run, {}, [] {
                        ApiSpec a;
                        a.offered = false;  // a shell's business, not a script's
                        return a;
                    }()});
}

} // namespace app::cli
