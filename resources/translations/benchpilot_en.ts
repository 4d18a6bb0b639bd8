<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>app::ApiStatusButton</name>
    <message numerus="yes">
        <source>API: %n client(s)</source>
        <translation>
            <numerusform>API: %n client</numerusform>
            <numerusform>API: %n clients</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::CalibrationScreen</name>
    <message numerus="yes">
        <source>Imported %n reading(s) from %1: results in %2.</source>
        <translation>
            <numerusform>Imported %n reading from %1: results in %2.</numerusform>
            <numerusform>Imported %n readings from %1: results in %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::PatternScreen</name>
    <message numerus="yes">
        <source>%n samples say little of a largest error</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::words::EventWords</name>
    <message numerus="yes">
        <source>axis %1: a compensation table of %Ln points installed, not yet enabled</source>
        <comment>device.why.comp_installed_table</comment>
        <translation>
            <numerusform>axis %1: a compensation table of %Ln point installed, not yet enabled</numerusform>
            <numerusform>axis %1: a compensation table of %Ln points installed, not yet enabled</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>axis %1: a compensation table of %Ln points per direction installed, not yet enabled</source>
        <comment>device.why.comp_installed_table_per_direction</comment>
        <translation>
            <numerusform>axis %1: a compensation table of %Ln point per direction installed, not yet enabled</numerusform>
            <numerusform>axis %1: a compensation table of %Ln points per direction installed, not yet enabled</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::words::RecipeWords</name>
    <message numerus="yes">
        <source>running %1: %Ln operations, about %2; log %3</source>
        <comment>recipe.run.started</comment>
        <translation>
            <numerusform>running %1: %Ln operation, about %2; log %3</numerusform>
            <numerusform>running %1: %Ln operations, about %2; log %3</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 finished: %Ln operations</source>
        <comment>recipe.run.finished</comment>
        <translation>
            <numerusform>%1 finished: %Ln operation</numerusform>
            <numerusform>%1 finished: %Ln operations</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::words::ScanWords</name>
    <message numerus="yes">
        <source>a polygon needs at least 3 vertices (got %Ln)</source>
        <comment>scan.region.too_few_vertices</comment>
        <translation>
            <numerusform>a polygon needs at least 3 vertices (got %Ln)</numerusform>
            <numerusform>a polygon needs at least 3 vertices (got %Ln)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ui::words::TuningWords</name>
    <message numerus="yes">
        <source>no Kp with a sustained oscillation after %Ln trials</source>
        <comment>tuning.ultimate.no_sustained</comment>
        <translation>
            <numerusform>no Kp with a sustained oscillation after %Ln trial</numerusform>
            <numerusform>no Kp with a sustained oscillation after %Ln trials</numerusform>
        </translation>
    </message>
</context>
</TS>
