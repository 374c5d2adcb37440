@rem minigolf launcher for Windows (replaces the script Gradle generates): one JVM.
@rem JAVA_HOME picks the Java (17 or newer); JAVA_OPTS and MINIGOLF_OPTS add JVM options.
@echo off
setlocal
set "APP_HOME=%~dp0.."
if defined JAVA_HOME (
    set "JAVA_EXE=%JAVA_HOME%\bin\java.exe"
) else (
    set "JAVA_EXE=java.exe"
    where java.exe >NUL 2>&1 || (
        echo minigolf: no Java found: install Java 17 or newer, or set JAVA_HOME 1>&2
        exit /b 1
    )
)
"%JAVA_EXE%" -Xss4m --enable-native-access=ALL-UNNAMED %JAVA_OPTS% %MINIGOLF_OPTS% -classpath "%APP_HOME%\lib\*" minigolf.Main %*
exit /b %ERRORLEVEL%
