#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <optional>

namespace opentop {

class ResultDatabase;

struct RecipeApproval
{
    QString id; // a UUID; every unit record names it
    QString checksum;
    QString recipeName;
    QString revision;
    QString approver;        // user name
    QDateTime approved;      // UTC
    QString station;         // where it was approved
    bool superseded = false; // a later checksum of the same recipe name was approved
};

// The recipe approvals of the results database (schema version 6). A managed station runs a
// recipe only when its checksum has an approval that no later approval of the same recipe name
// superseded: an edited recipe has another checksum and is a draft until it is approved.
class RecipeApprovals
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeApprovals)
public:
    explicit RecipeApprovals(ResultDatabase& database);

    // The approval in force for `checksum`; nullopt with *error empty when there is none.
    std::optional<RecipeApproval> current(const QString& checksum, QString* error);
    // Approves (who may is the caller's check): the recipe's earlier approvals of other checksums
    // become superseded, in one transaction. An approval already in force is returned as it is.
    std::optional<RecipeApproval> approve(const QString& recipeName, const QString& revision,
                                          const QString& checksum, const QString& approver,
                                          const QString& station, QString* error);

    // "approved by NAME on DATE" or why the recipe does not run, for screens and the CLI.
    static QString draftText(const QString& recipeName, const QString& revision);

private:
    ResultDatabase& database_;
};

} // namespace opentop
