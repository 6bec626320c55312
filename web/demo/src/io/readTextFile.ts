/** Largest file the demo reads (bigger ones are refused with a message). */
export const MAX_FILE_BYTES = 64 * 1024 * 1024;

export async function readTextFile(file: File): Promise<string> {
  if (file.size > MAX_FILE_BYTES) {
    throw new Error(`${file.name} is ${(file.size / 1e6).toFixed(0)} MB; the demo reads files up to ${MAX_FILE_BYTES / 1024 / 1024} MB`);
  }
  return file.text();
}
